package org.emini.harness.fuzz.world;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Mirroring a world in x mirrors its motion (round-off without contacts; 0.5 px + 1% with them) (MirrorRelation: its Javadoc gives the tolerance and why), over eight seeded worlds of each kind. */
class MirrorRelationTest {
    @ParameterizedTest(name = "separated world {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 6, 7})
    void holdsWithContacts(int index) {
        RelationCases.holds(new MirrorRelation(), index, Profile.SEPARATED);
    }

    @ParameterizedTest(name = "smooth world {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 6, 7})
    void holdsWithoutContacts(int index) {
        RelationCases.holds(new MirrorRelation(), index, Profile.SMOOTH);
    }
}
