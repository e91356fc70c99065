package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * A heavy box dropped on a light one lying on the ground, elasticity 0: a rigid collision stops the
 * heavy box, so it must neither bounce nor knock the light one away. One Gauss–Seidel relax pass per
 * substep moves velocity across a 1:100 mass ratio at about 1% per pass, which left the soft pass's
 * push in the heavy box (it rebounded at 160 px/s); the impact relax passes take it out.
 */
class MassRatioImpactTest {
    /** Drops the heavy box from 270 px above the light box (190 px/s at impact) and returns its fastest rise. */
    private static float fastestRise(float heavyMass, int impactPasses, Body[] out) {
        World world = new World();
        world.getSolverSettings().setImpactRelaxPasses(impactPasses);
        Body[] pair = Scenes.heavyOnLight(world, heavyMass, -300f);
        Body light = pair[0];
        Body heavy = pair[1];
        float rise = 0f;
        for (int tick = 0; tick < 200; tick++) {
            world.tick();
            rise = Math.max(rise, -heavy.getVelocityY());
        }
        out[0] = heavy;
        out[1] = light;
        return rise;
    }

    @Test
    void aHeavyBoxLandsOnALightOneWithoutBouncing() {
        Body[] bodies = new Body[2];
        for (float mass : new float[] {10f, 100f}) {
            float rise = fastestRise(mass, new SolverSettings().getImpactRelaxPasses(), bodies);
            System.out.printf("mass %.0f on 1, dropped at 190 px/s: fastest rise %.2f px/s, light box moved %.2f px%n",
                mass, rise, bodies[1].getX());
            // pymunk (10 iterations) rises at 15 px/s after this impact; push-out alone is capped at 60.
            assertTrue(rise < 20f, "mass " + mass + ": the heavy box rose at " + rise + " px/s with elasticity 0");
            assertEquals(-40f, bodies[0].getY(), 0.5f, "mass " + mass + ": the heavy box rests on the light one");
            // Measured: the light box slides 2.0 px under the 1:100 impact (float asymmetry in the squeeze).
            assertEquals(bodies[0].getX(), bodies[1].getX(), 5f, "mass " + mass + ": the light box stays under it");
            assertEquals(-10f, bodies[1].getY(), 0.5f, "mass " + mass + ": the light box stays on the ground");
        }
    }

    @Test
    void withoutImpactPassesTheSameDropBounces() {
        // Box2D v3's plain soft step: what the impact passes exist for (the test above cannot pass by luck).
        float rise = fastestRise(100f, 0, new Body[2]);
        System.out.printf("mass 100 on 1 without impact passes: fastest rise %.1f px/s%n", rise);
        assertTrue(rise > 100f, "the plain soft step rose at " + rise + " px/s");
    }
}
