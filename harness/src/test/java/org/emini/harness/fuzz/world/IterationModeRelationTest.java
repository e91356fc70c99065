package org.emini.harness.fuzz.world;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Dynamic iterations move separated bodies as fixed iterations do, within 1 px + 2% of the motion (IterationModeRelation: its Javadoc gives the tolerance and why), over eight seeded worlds. */
class IterationModeRelationTest {
    @ParameterizedTest(name = "world {0}")
    @ValueSource(ints = {0, 1, 2, 3, 4, 5, 6, 7})
    void holds(int index) {
        RelationCases.holds(new IterationModeRelation(), index, Profile.SEPARATED);
    }
}
