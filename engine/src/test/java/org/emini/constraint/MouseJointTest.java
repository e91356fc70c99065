package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A mouse joint dragging a box 400 px with its pull capped at m·a (a = 100 px/s²), without gravity:
 * while the spring's demand exceeds the cap the box accelerates at exactly a and the joint reports
 * the cap; it reaches the target in the time of a body limited to a that runs up at a and brakes at
 * 0.9·a (the joint's braking margin), without overshooting, and settles on it.
 */
class MouseJointTest {
    private static final float DISTANCE = 400f;
    private static final float ACCELERATION = 100f;

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void reachesTheTargetNoFasterThanTheCapAllows(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        world.setGravity(0f, 0f);
        Body box = new Body(0f, 0f, Shape.createRectangle(20f, 20f), true);
        world.addBody(box);
        float cap = box.getMass() * ACCELERATION;
        MouseJoint drag = new MouseJoint(box, 0f, 0f, cap);
        drag.setSpring(5f, 1f);
        drag.setTarget(DISTANCE, 0f);
        world.addConstraint(drag);
        double h = world.getTimestep() / world.getConstraintIterations();

        // The first second: capped all along (the spring wants m·ω²·300 px and more).
        int ticks = (int) Math.round(ticksPerSecond);
        Rigs.run(world, ticks);
        double t = ticks * world.getTimestep();
        assertEquals(0.5 * ACCELERATION * t * (t + h), box.getX(), 1e-3 * box.getX());
        assertEquals(cap, drag.getForce(), 1e-4 * cap);

        double arrival = -1.0;
        double peak = 0.0;
        double furthest = 0.0;
        for (int i = ticks; i < 20 * ticksPerSecond; i++) {
            world.tick();
            peak = Math.max(peak, drag.getForce());
            furthest = Math.max(furthest, box.getX());
            if (arrival < 0.0 && Math.abs(box.getX() - DISTANCE) < 1f) {
                arrival = (i + 1) * world.getTimestep();
            }
        }
        // Bang-bang at a, braking at 0.9·a (the joint's margin): D₁ = 0.9·D/1.9 run up, D₂ = D/1.9 braked.
        double up = 0.9 * DISTANCE / 1.9;
        double down = DISTANCE / 1.9;
        double bangBang = Math.sqrt(2 * up / ACCELERATION) + Math.sqrt(2 * down / (0.9 * ACCELERATION));
        System.out.printf("mouse %.0f ticks/s: within 1 px of the target at %.3f s (bang-bang %.3f s, at full braking"
            + " 2·√(D/a) %.3f s), overshoot %.4f px, peak force %.4f cap, at the end %.5f px off%n", ticksPerSecond,
            arrival, bangBang, 2.0 * Math.sqrt(DISTANCE / ACCELERATION), furthest - DISTANCE, peak / cap,
            box.getX() - DISTANCE);
        assertEquals(bangBang, arrival, 0.05 * bangBang);
        assertTrue(furthest - DISTANCE < 0.5, "overshot by " + (furthest - DISTANCE));
        assertTrue(peak <= cap * 1.0001, "force over the cap: " + peak);
        assertEquals(DISTANCE, box.getX(), 0.01);
        assertEquals(0.0, box.getY(), 0.01);
    }
}
