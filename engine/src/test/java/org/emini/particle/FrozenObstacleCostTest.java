package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * Bodies frozen outside the simulation area cost particles nothing: the obstacle grid finds bodies
 * through the world's simulated list and broadphase, so the bodies it looks at per tick do not grow
 * with frozen bodies far from the particles (it used to loop over every body of the world).
 */
class FrozenObstacleCostTest {
    /** The bodies the obstacle grid looked at in the last of 40 ticks, with so many frozen bodies. */
    private static int visitedWith(int frozen) {
        World world = new World();
        world.addBody(new Body(0f, 100f, Shape.createRectangle(600f, 20f), false));
        for (int i = 0; i < 10; i++) {
            world.addBody(new Body(-200f + 40f * i, 50f, Shape.createRectangle(20f, 20f), true));
        }
        for (int i = 0; i < frozen; i++) {
            world.addBody(new Body(5000f + 30f * (i % 100), -30f * (i / 100), Shape.createRectangle(20f, 20f), true));
        }
        world.setSimulationArea(-400f, -400f, 400f, 400f);
        ParticleSystem particles = new ParticleSystem();
        ParticleEmitter e = new ParticleEmitter(100);
        e.setEmitPoint(0f, -100f);
        e.setCreationRate(50f, 0f);
        e.setSpeed(100f, 50f);
        e.setAngle(1.57f, 2f);
        particles.addEmitter(e);
        for (int t = 0; t < 40; t++) {
            world.tick();
            particles.step(world, world.getTimestep());
        }
        assertTrue(e.getParticleCount() > 50, "particles " + e.getParticleCount());
        return particles.grid.visited;
    }

    @Test
    void theBodiesLookedAtPerTickDoNotGrowWithFrozenBodiesElsewhere() {
        int without = visitedWith(0);
        assertTrue(without > 10, "visited " + without);
        assertEquals(without, visitedWith(3000));
    }
}
