package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * A fixed joint whose anchor sits far out on a small, heavy body (a 2 px circle welded through a
 * 400 px arm to a light off-centre polygon: the world fuzzer's shrunk finding, seed 2026, scene 167)
 * stays welded: solved as one 3×3 block the point and angle rows no longer undo each other (one after
 * the other they diverged to 10²⁰ px/s in eleven ticks).
 */
class WeldLeverTest {
    @Test
    void aSmallBodyWeldedThroughALongArmStaysWelded() {
        World world = new World();
        Shape light = Shape.createPolygon(-31.125f, -23.0625f, -7.75f, -28.625f, 7.8125f, -8.375f, -2.875f, 3f,
            -32.6875f, -2.5625f, -35.3125f, -17.125f);
        light.setMass(0.453125f);
        Shape small = Shape.createCircle(2f);
        small.setMass(5.3125f);
        Body polygon = new Body(-43.5625f, -185.5f, light, true);
        Body circle = new Body(350.75f, -92.3125f, small, true);
        circle.setAngle(3.07421875f);
        circle.setVelocity(-38.3125f, -28.0625f);
        circle.setAngularVelocity(3.2763671875f);
        world.addBody(polygon);
        world.addBody(circle);
        Joint weld = new Joint(circle, polygon, 387.125f, 119.5f, 13f, 8.4375f, true);
        world.addConstraint(weld);
        float fastest = 0f;
        for (int t = 0; t < 100; t++) {
            world.tick();
            fastest = Math.max(fastest, (float) Math.hypot(polygon.getVelocityX(), polygon.getVelocityY()));
        }
        // Gravity alone brings it to 100 px/s² × 5 s; a flung pair goes far beyond.
        assertTrue(fastest < 1000f, "fastest " + fastest + " px/s");
        assertTrue(Rigs.gap(weld) < 0.5, "gap " + Rigs.gap(weld));
    }
}
