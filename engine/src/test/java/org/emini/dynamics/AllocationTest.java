package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Test;

/**
 * A tick allocates nothing in steady state. Counted with the JVM's per-thread allocation counter:
 * a count of bytes, not a timing, so it is exact and repeatable.
 */
class AllocationTest {
    @Test
    void steadyStateTicksAllocateNothing() {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        World world = DeterminismTest.rain(3);
        // Let the pile form so every array has grown to the scene.
        for (int t = 0; t < 400; t++) {
            world.tick();
        }
        long thread = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(thread);
        long calibration = threads.getThreadAllocatedBytes(thread) - before;
        before = threads.getThreadAllocatedBytes(thread);
        for (int t = 0; t < 100; t++) {
            world.tick();
        }
        long allocated = threads.getThreadAllocatedBytes(thread) - before - calibration;
        assertEquals(0L, allocated, "bytes allocated by 100 ticks of a settled pile");
    }
}
