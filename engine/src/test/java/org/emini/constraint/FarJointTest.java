package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A joint created far from satisfied pulls its bodies together at a bounded speed (the settings'
 * joint push cap) and then holds, with or without a static body near: it used to fling them at
 * 10⁷ px/s, the gap growing to 13,000 px.
 */
class FarJointTest {
    @ParameterizedTest(name = "fixed {0}, ground {1}, anchor {2} px off")
    @CsvSource({"true, true, 1000", "true, false, 1000", "false, true, 1000", "true, true, 200", "false, false, 5000"})
    void aJointFarFromSatisfiedClosesAtABoundedSpeedAndHolds(boolean fixed, boolean ground, float offset) {
        World world = new World();
        if (ground) {
            world.addBody(new Body(0f, 100f, Shape.createRectangle(20000f, 20f), false));
        }
        Body a = new Body(0f, 0f, Shape.createRectangle(40f, 10f), true);
        Body b = new Body(0f, 0f, Shape.createRectangle(40f, 10f), true);
        world.addBody(a);
        world.addBody(b);
        Joint joint = new Joint(a, b, 0f, 0f, offset, 0f, fixed);
        world.addConstraint(joint);
        float cap = world.getSolverSettings().getJointPushMaxVelocity();
        float fastest = 0f;
        int ticks = (int) (20f * (offset / cap + 4f));
        for (int t = 0; t < ticks; t++) {
            world.tick();
            for (Body body : new Body[] {a, b}) {
                fastest = Math.max(fastest, (float) Math.hypot(body.getVelocityX(), body.getVelocityY()));
            }
        }
        // The anchors close at the cap; each body's centre may move faster by its rotation about them.
        assertTrue(fastest < 3f * cap, "fastest body " + fastest + " px/s, cap " + cap);
        // Then it holds: a soft weld on a lever this long sags by a small fraction of the lever.
        assertTrue(Rigs.gap(joint) < Math.max(0.5, 0.002 * offset), "gap after " + ticks + " ticks: " + Rigs.gap(joint));
    }
}
