package org.emini.harness.fuzz.world;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** A listener, an emitter at rate 0, an empty or far landscape and an event that never holds change nothing, bit for bit (IdleFeaturesRelation: its Javadoc gives the tolerance and why), over eight seeded worlds. */
class IdleFeaturesRelationTest {
    @ParameterizedTest(name = "world {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 6, 7})
    void holds(int index) {
        RelationCases.holds(new IdleFeaturesRelation(), index, Profile.GENERAL);
    }
}
