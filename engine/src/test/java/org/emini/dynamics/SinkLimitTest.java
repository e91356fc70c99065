package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.constraint.Joint;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * A soft contact is a spring whose stiffness follows the lighter body's mass, so a heavy box resting
 * on a light one sinks by (1 + M/m) g / ω²: at 20 ticks per second and 10 iterations (ω = 2π·50 Hz)
 * a 1:1000 pair sinks 1.01 px. The solver takes more substeps in such ticks until the sink is under
 * the limit (0.5 px: 15 substeps, where ω = 2π·75 Hz gives 0.45 px), and only there.
 */
class SinkLimitTest {
    private static final float G = 100f;

    /** The deepest overlap of the heavy box into the light one over ticks 20 to 200 (the first second settles). */
    private static float deepestSink(World world, Body light, Body heavy) {
        float deepest = 0f;
        for (int tick = 0; tick < 200; tick++) {
            world.tick();
            if (tick >= 20) {
                deepest = Math.max(deepest, (heavy.getY() + 20f) - (light.getY() - 10f));
            }
        }
        return deepest;
    }

    @Test
    void aThousandfoldHeavierBoxSinksUnderOnePixelAtTheDefaults() {
        World world = new World();
        Body[] b = Scenes.heavyOnLight(world, 1000f, -40f);
        float sink = deepestSink(world, b[0], b[1]);
        assertTrue(sink < 1f, "sink " + sink + " px");
        assertEquals(15, world.getLastIterationCount(), "the fewest substeps whose contact frequency holds the sink under 0.5 px");
        assertTrue(Math.abs(b[0].getX()) < 0.5f && Math.abs(b[1].getX()) < 0.5f,
            "the pair stays stacked: light x " + b[0].getX() + ", heavy x " + b[1].getX());
    }

    @Test
    void withoutTheLimitTheSinkIsTheSoftContactsClosedForm() {
        World world = new World();
        world.getSolverSettings().setSinkLimit(Float.POSITIVE_INFINITY);
        Body[] b = Scenes.heavyOnLight(world, 1000f, -40f);
        float sink = deepestSink(world, b[0], b[1]);
        double omega = 2 * Math.PI * 50;
        double closedForm = 1001 * G / (omega * omega);
        // The limit is what holds it: without it the pair sinks by the closed form, plus the slop and jitter.
        assertTrue(sink > closedForm && sink < closedForm + 0.5, "sink " + sink + " px, closed form " + closedForm);
        assertEquals(10, world.getLastIterationCount());
    }

    @Test
    void theFactorCapsTheSubsteps() {
        World world = new World();
        world.getSolverSettings().setSinkSubstepFactor(1.2f);
        Body[] b = Scenes.heavyOnLight(world, 1000f, -40f);
        deepestSink(world, b[0], b[1]);
        assertEquals(12, world.getLastIterationCount());
    }

    @Test
    void equalBodiesNeverPayForIt() {
        World world = new World();
        Scenes.tower(world, 20, 20f);
        for (int tick = 0; tick < 100; tick++) {
            world.tick();
            assertEquals(10, world.getLastIterationCount(), "tick " + tick);
        }
        World pyramid = new World();
        Scenes.pyramid(pyramid, 20, 20f);
        for (int tick = 0; tick < 100; tick++) {
            pyramid.tick();
            assertEquals(10, pyramid.getLastIterationCount(), "tick " + tick);
        }
    }

    @Test
    void aHeavyBodyHeldByAJointDoesNotLoadWhatItTouches() {
        World world = new World();
        Body[] b = Scenes.heavyOnLight(world, 1000f, -40f);
        Body anchor = new Body(0f, -300f, Shape.createRectangle(10f, 10f), false);
        world.addBody(anchor);
        world.addConstraint(Joint.atWorldPoint(anchor, b[1], 0f, -40f, false));
        for (int tick = 0; tick < 100; tick++) {
            world.tick();
            assertEquals(10, world.getLastIterationCount(), "tick " + tick);
        }
    }
}
