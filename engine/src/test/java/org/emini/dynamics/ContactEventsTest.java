package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;
import java.util.Random;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Contact events: begins and ends balance whatever the application does between and during ticks,
 * hits come at the approach speed of free fall, and a pre-solve listener makes a one-way platform.
 */
class ContactEventsTest {
    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void beginsAndEndsBalanceTheTouchingContacts(long seed) {
        Random random = new Random(seed);
        World world = new World();
        world.setTicksPerSecond(60);
        world.addBody(new Body(0f, 10f, Shape.createRectangle(600f, 20f), false));
        Landscape land = new Landscape();
        land.addSegment(-300f, -200f, -300f, 0f);
        land.addSegment(300f, -200f, 300f, 0f);
        world.setLandscape(land);
        Map<String, Integer> touching = new HashMap<>();
        for (int t = 0; t < 400; t++) {
            if (t % 7 == 0 && world.getBodyCount() < 40) {
                float size = 6f + 20f * random.nextFloat();
                Shape s = random.nextBoolean() ? Shape.createCircle(size / 2f) : Shape.createRectangle(size, size * 0.7f);
                world.addBody(new Body(-250f + 500f * random.nextFloat(), -150f, s, true));
            }
            int n = world.getBodyCount();
            if (t % 11 == 5 && n > 2) {
                world.removeBody(world.getBody(1 + random.nextInt(n - 1)));
            }
            n = world.getBodyCount();
            if (t % 13 == 3 && n > 2) {
                Body b = world.getBody(1 + random.nextInt(n - 1));
                b.setShape(Shape.createCircle(4f + 8f * random.nextFloat()));
            }
            if (t % 17 == 9 && n > 2) {
                world.getBody(1 + random.nextInt(n - 1)).setPosition(0f, -400f);
            }
            world.tick();
            StepData step = world.getStepData();
            for (int i = 0; i < step.getEndCount(); i++) {
                String key = key(step.getEndBodyA(i), step.getEndBodyB(i));
                int left = touching.getOrDefault(key, 0) - 1;
                assertTrue(left >= 0, "an end without a begin: " + key + " in tick " + t);
                touching.put(key, left);
            }
            for (int i = 0; i < step.getBeginCount(); i++) {
                Contact c = step.getBeginContact(i);
                touching.merge(key(c.getBodyA(), c.getBodyB()), 1, Integer::sum);
            }
            Map<String, Integer> now = new HashMap<>();
            for (int i = 0; i < world.getContactCount(); i++) {
                Contact c = world.getContact(i);
                if (c.isTouching()) {
                    now.merge(key(c.getBodyA(), c.getBodyB()), 1, Integer::sum);
                }
            }
            touching.values().removeIf(v -> v == 0);
            assertEquals(now, touching, "touching contacts after tick " + t);
        }
        while (world.getBodyCount() > 0) {
            world.removeBody(world.getBody(world.getBodyCount() - 1));
        }
        world.tick();
        StepData step = world.getStepData();
        for (int i = 0; i < step.getEndCount(); i++) {
            touching.merge(key(step.getEndBodyA(i), step.getEndBodyB(i)), -1, Integer::sum);
        }
        touching.values().removeIf(v -> v == 0);
        assertTrue(touching.isEmpty(), "every begin ended once its bodies were gone: " + touching);
    }

    @Test
    void aContactApartReportsTheNormalOfItsLastTouchOrNone() {
        // A box rests against a wall (a sideways normal); another falls onto the ground from 3 px, found
        // apart while the fat boxes overlap, lands, then is thrown up. Apart, the contact's normal is
        // (0, 0) before it first touches and the ground's after, never another contact's.
        World world = new World();
        world.setTicksPerSecond(60);
        world.setGravity(0f, 200f);
        Body ground = new Body(0f, 10f, Shape.createRectangle(600f, 20f), false);
        world.addBody(ground);
        world.addBody(new Body(-100f, -40f, Shape.createRectangle(20f, 100f), false));
        world.addBody(new Body(-80f, -10f, Shape.createRectangle(20f, 20f), true));
        Body faller = new Body(100f, -13f, Shape.createRectangle(20f, 20f), true);
        world.addBody(faller);
        world.tick();
        Contact onGround = null;
        for (int i = 0; i < world.getContactCount(); i++) {
            Contact c = world.getContact(i);
            if (c.getBodyA() == faller || c.getBodyB() == faller) {
                onGround = c;
            }
        }
        assertTrue(onGround != null && onGround.getPointCount() == 0, "found apart first");
        assertEquals(0f, onGround.getNormalX());
        assertEquals(0f, onGround.getNormalY());
        for (int t = 0; t < 60 && onGround.getPointCount() == 0; t++) {
            world.tick();
        }
        assertTrue(onGround.getPointCount() > 0, "landed");
        float nx = onGround.getNormalX();
        float ny = onGround.getNormalY();
        assertEquals(1f, Math.abs(ny), 1e-5f);
        faller.setVelocity(0f, -300f);
        for (int t = 0; t < 3; t++) {
            world.tick();
        }
        assertTrue(onGround.getHandle() != 0L && onGround.getPointCount() == 0, "thrown apart, the contact kept");
        assertEquals(nx, onGround.getNormalX());
        assertEquals(ny, onGround.getNormalY());
    }

    private static String key(Body a, Body b) {
        int ia = a.getId();
        int ib = b == null ? -1 : b.getId();
        return Math.min(ia, ib) + "-" + Math.max(ia, ib);
    }

    @Test
    void aDroppedBallHitsAtItsFreeFallSpeed() {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setHitEventThreshold(20f);
        world.addBody(new Body(0f, 10f, Shape.createRectangle(400f, 20f), false));
        Body ball = new Body(0f, -100f, Shape.createCircle(5f), true);
        world.addBody(ball);
        int hits = 0;
        float speed = 0f;
        for (int t = 0; t < 300; t++) {
            world.tick();
            StepData step = world.getStepData();
            for (int i = 0; i < step.getHitCount(); i++) {
                hits++;
                speed = step.getHitSpeed(i);
                assertEquals(0f, step.getHitX(i), 0.5f);
                assertEquals(0f, step.getHitY(i), 1f, "the point lies on the ground's top face");
            }
        }
        assertEquals(1, hits, "one impact; resting contacts approach slower than the threshold");
        // The ball's bottom falls 95 px under 100 px/s²: v = sqrt(2·100·95) = 137.8 px/s.
        assertEquals(Math.sqrt(2.0 * 100.0 * 95.0), speed, 0.05 * 137.8);
    }

    @Test
    void noHitsUnlessAThresholdIsSet() {
        World world = new World();
        world.addBody(new Body(0f, 10f, Shape.createRectangle(400f, 20f), false));
        world.addBody(new Body(0f, -100f, Shape.createCircle(5f), true));
        for (int t = 0; t < 100; t++) {
            world.tick();
            assertEquals(0, world.getStepData().getHitCount());
        }
    }

    @Test
    void aPreSolveListenerMakesAOneWayPlatform() {
        World world = new World();
        world.setTicksPerSecond(60);
        Body platform = new Body(0f, 0f, Shape.createRectangle(200f, 10f), false);
        world.addBody(platform);
        Body box = new Body(0f, 100f, Shape.createRectangle(20f, 20f), true);
        box.setVelocity(0f, -250f);
        world.addBody(box);
        // Solid only for a body whose bottom is above the platform's top (y grows downwards).
        world.setPreSolveListener(c -> {
            Body other = c.getOther(platform);
            return other == null || other.getY() + 10f <= platform.getY() - 5f + 1f;
        });
        float highest = Float.MAX_VALUE;
        for (int t = 0; t < 600; t++) {
            world.tick();
            highest = Math.min(highest, box.getY());
        }
        // From below it passes: v² / 2g = 312 px up from y = 100.
        assertEquals(100.0 - 250.0 * 250.0 / 200.0, highest, 5.0);
        // From above it lands and rests on the top face (y = −5 − 10).
        assertEquals(-15.0, box.getY(), 1.0);
        assertEquals(0.0, box.getVelocityY(), 1.0);
    }
}
