package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.AllocationWindows;
import org.junit.jupiter.api.Test;

/**
 * Ticks with joints, springs, motors, a user constraint, an external force and events of every type
 * allocate nothing in steady state (the JVM's per-thread allocated-bytes counter: exact, not timed).
 */
class ConstraintAllocationTest {
    @Test
    void ticksWithConstraintsForcesAndEventsAllocateNothing() {
        Machine machine = new Machine(5);
        // Let every array grow to the scene and the pile settle: a trigger-once event's memory
        // grows (legitimately) whenever a body meets its condition for the first time.
        machine.run(1000);
        int before = machine.notifications;
        AllocationWindows allocated = AllocationWindows.measure(5, () -> machine.run(100));
        assertTrue(machine.notifications > before + 100, "the events fired " + (machine.notifications - before) + " times");
        assertEquals(0L, allocated.least(), "100 ticks, " + allocated);
    }
}
