package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Test;

/**
 * A tick allocates nothing in steady state. Counted with the JVM's per-thread allocation counter:
 * a count of bytes, not a timing, so it is exact and repeatable.
 */
class AllocationTest {
    /** Bytes the current thread allocated while running the work, less the counter's own cost. */
    private static long bytesAllocatedBy(Runnable work) {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(thread);
        long calibration = threads.getThreadAllocatedBytes(thread) - before;
        before = threads.getThreadAllocatedBytes(thread);
        work.run();
        return threads.getThreadAllocatedBytes(thread) - before - calibration;
    }

    @Test
    void steadyStateTicksAllocateNothing() {
        World world = DeterminismTest.rain(3);
        // Let the pile form so every array has grown to the scene.
        for (int t = 0; t < 400; t++) {
            world.tick();
        }
        long allocated = bytesAllocatedBy(() -> {
            for (int t = 0; t < 100; t++) {
                world.tick();
            }
        });
        assertEquals(0L, allocated, "bytes allocated by 100 ticks of a settled pile");
    }

    /**
     * Landscape contacts, multi-shape contacts and a simulation area that moves every tick (so
     * bodies freeze and wake) allocate nothing either.
     */
    @Test
    void ticksWithLandscapeMultiShapesAndAMovingAreaAllocateNothing() {
        World world = Terrain.rain(2000, 120, 1200f, 4);
        for (int t = 0; t < 300; t++) {
            world.tick();
        }
        Runnable sweep = () -> {
            for (int t = 0; t < 200; t++) {
                float x = -1400f + 14f * t;
                world.setSimulationArea(x, -1000f, x + 600f, 1000f);
                world.tick();
            }
        };
        // Once so that every array has grown to the scene, then counted.
        sweep.run();
        assertEquals(0L, bytesAllocatedBy(sweep), "bytes allocated by 200 ticks with a moving area");
    }
}
