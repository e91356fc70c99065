package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The same scene with constraints, forces and events gives bit-identical results, events included. */
class ConstraintDeterminismTest {
    @Test
    void twoRunsWithConstraintsAndEventsAreBitIdentical() {
        Machine a = new Machine(11);
        Machine b = new Machine(11);
        for (int t = 0; t < 300; t += 50) {
            a.run(50);
            b.run(50);
            assertEquals(a.hash(), b.hash(), "tick " + t);
        }
        assertEquals(a.notifications, b.notifications);
    }

    @Test
    void dynamicIterationsAreDeterministicToo() {
        Machine a = new Machine(12);
        Machine b = new Machine(12);
        a.world.setConstraintIterationDynamic(true);
        b.world.setConstraintIterationDynamic(true);
        a.run(300);
        b.run(300);
        assertEquals(a.hash(), b.hash());
    }
}
