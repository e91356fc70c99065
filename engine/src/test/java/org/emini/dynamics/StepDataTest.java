package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * The step data tells what a tick did: each simulated body's start pose is exactly its pose before
 * the tick, and a contact's touching begins and ends once per landing and lift-off, never
 * flickering while a body rests.
 */
class StepDataTest {
    @Test
    void startPosesAreThePosesBeforeTheTick() {
        World world = new World();
        world.addBody(new Body(0f, 10f, Shape.createRectangle(400f, 20f), false));
        Body[] boxes = new Body[5];
        for (int i = 0; i < boxes.length; i++) {
            boxes[i] = new Body(-60f + 30f * i, -20f - 25f * i, Shape.createRectangle(20f, 20f), true);
            boxes[i].setAngularVelocity(0.3f * i);
            world.addBody(boxes[i]);
        }
        float[] x = new float[5];
        float[] y = new float[5];
        float[] a = new float[5];
        for (int t = 0; t < 120; t++) {
            for (int i = 0; i < 5; i++) {
                x[i] = boxes[i].getX();
                y[i] = boxes[i].getY();
                a[i] = boxes[i].getAngle();
            }
            world.tick();
            StepData step = world.getStepData();
            assertEquals(5, step.getBodyCount());
            assertEquals(t, step.getTick());
            for (int i = 0; i < 5; i++) {
                int k = step.indexOf(boxes[i]);
                assertSame(boxes[i], step.getBody(k));
                assertEquals(Float.floatToIntBits(x[i]), Float.floatToIntBits(step.getStartX(k)));
                assertEquals(Float.floatToIntBits(y[i]), Float.floatToIntBits(step.getStartY(k)));
                assertEquals(Float.floatToIntBits(a[i]), Float.floatToIntBits(step.getStartAngle(k)));
            }
        }
        assertEquals(-1, world.getStepData().indexOf(world.getBody(0)), "the static ground is not simulated");
    }

    @Test
    void aLandingBeginsTouchingOnceAndALiftEndsIt() {
        World world = new World();
        world.setTicksPerSecond(60);
        Body ground = new Body(0f, 10f, Shape.createRectangle(400f, 20f), false);
        world.addBody(ground);
        Body box = new Body(0f, -100f, Shape.createRectangle(20f, 20f), true);
        world.addBody(box);
        int begins = 0;
        int ends = 0;
        int landedAt = -1;
        for (int t = 0; t < 600; t++) {
            world.tick();
            StepData step = world.getStepData();
            for (int i = 0; i < step.getBeginCount(); i++) {
                Contact c = step.getBeginContact(i);
                assertTrue(c.isTouching());
                assertTrue(c.getBodyA() == box || c.getBodyB() == box);
                begins++;
                landedAt = t;
            }
            ends += step.getEndCount();
        }
        assertEquals(1, begins, "one landing, no flicker while resting for 10 s");
        assertEquals(0, ends);
        // The box fell 100 px from rest under 100 px/s²: about 1.41 s, tick ~85 at 60/s.
        assertTrue(landedAt >= 80 && landedAt <= 90, "landed at tick " + landedAt);
        box.setPosition(0f, -300f);
        world.tick();
        StepData step = world.getStepData();
        assertEquals(0, step.getBeginCount());
        assertEquals(1, step.getEndCount());
        Body a = step.getEndBodyA(0);
        Body b = step.getEndBodyB(0);
        assertTrue((a == box && b == ground) || (a == ground && b == box));
    }

    @Test
    void aBouncingBallBeginsAndEndsEachBounce() {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setLandscape(landscapeFloor());
        Shape ball = Shape.createCircle(5f);
        ball.setElasticity(1f);
        Body body = new Body(0f, -50f, ball, true);
        world.addBody(body);
        int begins = 0;
        int ends = 0;
        for (int t = 0; t < 600; t++) {
            world.tick();
            StepData step = world.getStepData();
            begins += step.getBeginCount();
            ends += step.getEndCount();
            for (int i = 0; i < step.getEndCount(); i++) {
                assertSame(body, step.getEndBodyA(i));
                assertNull(step.getEndBodyB(i), "a landscape segment has no body");
            }
            assertTrue(begins - ends == 0 || begins - ends == 1, "begin and end alternate");
        }
        // Falling 50 px (1 s) and bouncing back up: a bounce every 2 s, five in 10 s.
        assertTrue(begins >= 4 && begins <= 6, begins + " bounces");
    }

    private static Landscape landscapeFloor() {
        Landscape l = new Landscape();
        l.addSegment(-500f, 10f, 500f, 10f, Landscape.FACE_NONE);
        l.setElasticity(1f);
        return l;
    }
}
