package org.emini.harness.fuzz.world;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The bullet flag changes nothing while no body is fast, bit for bit (BulletRelation: its Javadoc gives the tolerance and why), over eight seeded worlds. */
class BulletRelationTest {
    @ParameterizedTest(name = "world {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 6, 7})
    void holds(int index) {
        RelationCases.holds(new BulletRelation(), index, Profile.GENERAL);
    }
}
