package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Contact impulses are equal and opposite, so with gravity off linear momentum is conserved to
 * rounding. Angular momentum is conserved when both bodies take an impulse at the same point: the
 * solver moves the tick's contact point with the pair (midway between where each body carried it),
 * up to a fifth of the smaller part's bounding radius, so only pairs that slide past each other faster
 * than that in one tick keep part of the first-order error of fixed anchors (Box2D v3's).
 */
class MomentumConservationTest {
    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void linearAndAngularMomentumAreConservedThroughCollisions(long seed) {
        Random random = new Random(seed);
        World world = new World();
        world.setGravity(0f, 0f);
        Shape[] shapes = {
            Shape.createRectangle(20f, 20f), Shape.createCircle(8f), Shape.createRegularPolygon(12f, 5),
            Shape.createRectangle(40f, 10f), Shape.createCircle(15f),
        };
        shapes[1].setMass(3f);
        shapes[3].setMass(0.5f);
        shapes[4].setElasticity(0.8f);
        shapes[0].setElasticity(0.5f);
        for (int i = 0; i < 30; i++) {
            Body b = new Body(random.nextFloat() * 300f, random.nextFloat() * 300f, shapes[i % shapes.length], true);
            b.setVelocity(random.nextFloat() * 200f - 100f, random.nextFloat() * 200f - 100f);
            b.setAngularVelocity(random.nextFloat() * 4f - 2f);
            b.setAngle(random.nextFloat() * 6f);
            world.addBody(b);
        }
        double[] before = momentum(world);
        int touching = 0;
        for (int t = 0; t < 200; t++) {
            world.tick();
            for (int k = 0; k < world.getContactCount(); k++) {
                touching += world.getContact(k).getPointCount();
            }
        }
        double[] after = momentum(world);
        assertTrue(touching > 50, "the scene must actually collide, contact points seen: " + touching);
        double scale = before[3];
        assertEquals(before[0], after[0], 1e-5 * scale, "px");
        assertEquals(before[1], after[1], 1e-5 * scale, "py");
        double angularScale = before[4];
        // Measured 4e-5 to 9.5e-4 of the scale (5.7e-4 to 2.3e-3 with the tick's arms, seeds 2 and 3 beyond this bound).
        assertEquals(before[2], after[2], 1.5e-3 * angularScale, "L");
    }

    @ParameterizedTest
    @ValueSource(ints = {20, 60})
    void spinningBoxesThatCollideOffCentreKeepAngularMomentum(int rate) {
        World world = new World();
        world.setTicksPerSecond(rate);
        world.setGravity(0f, 0f);
        Shape box = Shape.createRectangle(20f, 20f);
        box.setFriction(0.5f);
        Body a = new Body(-100f, 0f, box, true);
        a.setVelocity(50f, 0f);
        a.setAngularVelocity(2f);
        Body b = new Body(0f, 5f, box, true);
        b.setAngularVelocity(-1f);
        world.addBody(a);
        world.addBody(b);
        double worst = worstAngularDrift(world, 5 * rate);
        assertTrue(b.getVelocityX() > 10f, "the boxes collided");
        // closed-form/angular-momentum-through-contact: 11.8 with the tick's arms, pymunk 2.18.
        assertEquals(0.0, worst, 0.05, "angular momentum about the origin");
    }

    @Test
    void aSpinningRodThatStrikesABallKeepsAngularMomentum() {
        int rate = 20;
        // fast-bodies/spinning-rod-hits-ball: the rod's tip closes a gap of up to 80 px in a tick, so the
        // contact is speculative with a wide gap; its friction impulse must act at one point for both.
        World world = new World();
        world.setTicksPerSecond(rate);
        world.setGravity(0f, 0f);
        Shape rodShape = Shape.createRectangle(120f, 4f);
        rodShape.setMass(10f);
        Body rod = new Body(0f, 0f, rodShape, true);
        rod.setAngularVelocity(40f);
        Body ball = new Body(0f, 40f, Shape.createCircle(4f), true);
        world.addBody(rod);
        world.addBody(ball);
        double before = momentum(world)[2];
        double worst = worstAngularDrift(world, 2 * rate);
        assertTrue(Math.hypot(ball.getVelocityX(), ball.getVelocityY()) > 100f, "the ball was struck");
        // 29 of 480,000 (the common point follows the ball at most 0.8 px); 332 when only the ball's
        // arm ended on its surface; pymunk 13. At 60 ticks/s 520 (fast-bodies/spinning-rod-hits-ball-60hz).
        assertEquals(0.0, worst / Math.abs(before), 1e-4, "angular momentum about the origin, relative");
    }

    /** The largest change of the angular momentum about the origin over the next ticks. */
    private static double worstAngularDrift(World world, int ticks) {
        double before = momentum(world)[2];
        double worst = 0;
        for (int t = 0; t < ticks; t++) {
            world.tick();
            worst = Math.max(worst, Math.abs(momentum(world)[2] - before));
        }
        return worst;
    }

    /** px, py, angular momentum about the origin, Σ m|v|, Σ |I ω| + m |r × v|. */
    static double[] momentum(World world) {
        double px = 0;
        double py = 0;
        double l = 0;
        double scale = 0;
        double angularScale = 0;
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            double m = b.getMass();
            px += m * b.getVelocityX();
            py += m * b.getVelocityY();
            double orbital = m * ((double) b.getX() * b.getVelocityY() - (double) b.getY() * b.getVelocityX());
            double spin = b.getInertia() * b.getAngularVelocity();
            l += orbital + spin;
            scale += m * Math.hypot(b.getVelocityX(), b.getVelocityY());
            angularScale += Math.abs(orbital) + Math.abs(spin);
        }
        return new double[] {px, py, l, scale, angularScale};
    }
}
