package org.emini.harness.fuzz.world;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** A scene as YAML, as JSON and through a world file builds the same world (FormatRelation: its Javadoc gives the tolerance and why), over eight seeded worlds. */
class FormatRelationTest {
    @ParameterizedTest(name = "world {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 6, 7})
    void holds(int index) {
        RelationCases.holds(new FormatRelation(), index, Profile.SCENE);
    }
}
