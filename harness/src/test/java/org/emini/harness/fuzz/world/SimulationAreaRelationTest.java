package org.emini.harness.fuzz.world;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** A simulation area holding every body changes nothing, bit for bit (SimulationAreaRelation: its Javadoc gives the tolerance and why), over eight seeded worlds. */
class SimulationAreaRelationTest {
    @ParameterizedTest(name = "world {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 6, 7})
    void holds(int index) {
        RelationCases.holds(new SimulationAreaRelation(), index, Profile.GENERAL);
    }
}
