package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.AllocationWindows;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * A tick allocates nothing in steady state. Counted with the JVM's per-thread allocation counter
 * (a count of bytes, not a timing), best of a few windows: see {@link AllocationWindows} for the
 * JIT's one-off allocations the windows step over.
 */
class AllocationTest {

    @Test
    void steadyStateTicksAllocateNothing() {
        World world = DeterminismTest.rain(3);
        // Let the pile form so every array has grown to the scene.
        for (int t = 0; t < 400; t++) {
            world.tick();
        }
        AllocationWindows allocated = AllocationWindows.measure(5, () -> {
            for (int t = 0; t < 100; t++) {
                world.tick();
            }
        });
        assertEquals(0L, allocated.least(), "100 ticks of a settled pile, " + allocated);
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
        AllocationWindows allocated = AllocationWindows.measure(5, sweep);
        assertEquals(0L, allocated.least(), "200 ticks with a moving area, " + allocated);
    }
}
