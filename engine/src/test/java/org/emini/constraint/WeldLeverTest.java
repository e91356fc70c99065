package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * Joints whose anchor sits far out on a small body. A fixed joint whose anchor sits far out on a small, heavy body (a 2 px circle welded through a
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

    /**
     * A 4 px circle welded to a static body by a diagonal 326 px arm (the world fuzzer's seed 2,
     * passive:17, shrunk) is already where the joint wants it: it stays. Its block's entries are near
     * 3,500 and its determinant 0.006, which the entries' products lost to round-off: the circle left at
     * 3·10⁵ px/s in its first tick. A vertical or horizontal arm never showed it (the off-diagonal terms
     * vanish), nor does a loose pin of the same arm swing up beyond where it started.
     */
    @Test
    void aSmallCircleWeldedToTheGroundByADiagonalArmStaysPut() {
        for (boolean fixed : new boolean[] {true, false}) {
            World world = new World();
            world.setTicksPerSecond(60f);
            world.setConstraintIterations(12);
            world.setGravity(0f, 100f);
            Body ground = new Body(0f, 16.59375f, Shape.createRectangle(777.375f, 33.1875f), false);
            Shape small = Shape.createCircle(4.0625f);
            small.setMass(2.796875f);
            Body circle = new Body(167.875f, -263.375f, small, true);
            circle.setAngle(-0.9970703125f);
            world.addBody(ground);
            world.addBody(circle);
            Joint joint = Joint.atWorldPoint(ground, circle, 0f, 16.625f, fixed);
            world.addConstraint(joint);
            float fastest = 0f;
            float highest = circle.getY();
            for (int t = 0; t < 180; t++) {
                world.tick();
                fastest = Math.max(fastest, (float) Math.hypot(circle.getVelocityX(), circle.getVelocityY()));
                highest = Math.min(highest, circle.getY());
            }
            if (fixed) {
                assertTrue(fastest < 1e-3f, "welded: fastest " + fastest + " px/s");
            } else {
                // A pendulum from rest: as fast as its fall of at most 2 × 326 px allows, never above its start.
                assertTrue(fastest < (float) Math.sqrt(2 * 100 * 2 * 326), "pinned: fastest " + fastest + " px/s");
                assertTrue(highest > -263.375f - 0.5f, "pinned: rose to " + highest);
            }
            assertTrue(Rigs.gap(joint) < 0.5, (fixed ? "welded" : "pinned") + ": gap " + Rigs.gap(joint));
        }
    }
}
