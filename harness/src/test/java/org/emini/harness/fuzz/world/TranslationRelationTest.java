package org.emini.harness.fuzz.world;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Moving a world 8192 px away changes its relative motion by less than 0.25 px + 1% + the float step at that distance per substep (TranslationRelation: its Javadoc gives the tolerance and why), over eight seeded worlds of each kind. */
class TranslationRelationTest {
    @ParameterizedTest(name = "separated world {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 6, 7})
    void holdsWithContacts(int index) {
        RelationCases.holds(new TranslationRelation(), index, Profile.SEPARATED);
    }

    @ParameterizedTest(name = "smooth world {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 6, 7})
    void holdsWithoutContacts(int index) {
        RelationCases.holds(new TranslationRelation(), index, Profile.SMOOTH);
    }
}
