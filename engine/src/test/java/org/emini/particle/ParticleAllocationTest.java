package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.AllocationWindows;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * Ticks with 10,000 live particles bouncing in a box around moving bodies and landscape segments
 * allocate nothing:
 * counted with the JVM's per-thread allocation counter (bytes, not time), best of a few 100-tick
 * windows (see {@link AllocationWindows}).
 */
class ParticleAllocationTest {
    @Test
    void tenThousandParticlesInABoxAllocateNothingPerTick() {
        World world = new World();
        ParticleScenes.box(world, 300f, 10f, 0f);
        // A landscape ramp and ledge inside the box, hit by particles and bodies alike.
        world.getLandscape().addSegment(-300f, 150f, -50f, 290f);
        world.getLandscape().addSegment(100f, 100f, 250f, 100f);
        for (int i = 0; i < 20; i++) {
            Body b = new Body(-250f + 25f * i, -200f + 9f * (i % 5), Shape.createRectangle(18f, 12f), true);
            world.addBody(b);
        }
        ParticleEmitter e = ParticleScenes.spray(10_000, 4000f, 1000f, 500f, 400f);
        e.setElasticity(0.8f);
        e.setCreationRate(4000f, 1000f);
        world.addParticleEmitter(e);
        float[] positions = new float[20_000];
        for (int t = 0; t < 200; t++) {
            world.tick();
        }
        assertEquals(10_000, e.getParticleCount());
        float[] sum = new float[1];
        AllocationWindows allocated = AllocationWindows.measure(5, () -> {
            for (int t = 0; t < 100; t++) {
                world.tick();
                // Reading for drawing allocates nothing either.
                e.copyPositions(positions);
                for (int i = 0; i < e.getParticleCount(); i++) {
                    sum[0] += e.getX(i) + e.getY(i) + e.getAge(i);
                }
            }
        });
        assertEquals(0L, allocated.least(), "100 ticks with 10,000 particles, " + allocated);
        assertEquals(10_000, e.getParticleCount());
        assertTrue(sum[0] == sum[0]);
    }

    @Test
    void aWorldWithoutEmittersIsUntouched() {
        World world = new World();
        world.addBody(new Body(0f, 0f, Shape.createCircle(5f), true));
        world.tick();
        assertEquals(0, world.getParticleEmitterCount());
    }
}
