package org.emini.harness.fuzz.world;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Halving the timestep brings smooth motion closer to a run 32 times finer, down to 0.1 px (ConvergenceRelation: its Javadoc gives the tolerance and why), over eight seeded worlds. */
class ConvergenceRelationTest {
    @ParameterizedTest(name = "world {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 6, 7})
    void holds(int index) {
        RelationCases.holds(new ConvergenceRelation(), index, Profile.SMOOTH);
    }
}
