package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.TreeSet;
import org.emini.collision.Collider;
import org.emini.collision.Manifold;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Sensor bodies: nothing collides with them (a world with a sensor moves exactly as without it),
 * and their begin and end events track the exact overlaps that a brute-force test of every body
 * finds.
 */
class SensorTest {
    private static World rain(long seed, int count) {
        Random random = new Random(seed);
        World world = new World();
        world.setTicksPerSecond(60);
        world.addBody(new Body(0f, 10f, Shape.createRectangle(600f, 20f), false));
        for (int i = 0; i < count; i++) {
            float size = 5f + 15f * random.nextFloat();
            Shape s = random.nextBoolean() ? Shape.createCircle(size / 2f) : Shape.createRectangle(size, size);
            Body b = new Body(-250f + 500f * random.nextFloat(), -300f - 400f * random.nextFloat(), s, true);
            b.setAngle(random.nextFloat());
            world.addBody(b);
        }
        return world;
    }

    @Test
    void aSensorChangesNoMotion() {
        World plain = rain(3, 30);
        World sensed = rain(3, 30);
        Body sensor = new Body(0f, -100f, Shape.createRectangle(300f, 60f), false);
        sensor.setSensor(true);
        sensed.addBody(sensor);
        Body falling = new Body(40f, -100f, Shape.createCircle(8f), true);
        falling.setSensor(true);
        sensed.addBody(falling);
        for (int t = 0; t < 300; t++) {
            plain.tick();
            sensed.tick();
            for (int i = 0; i < plain.getBodyCount(); i++) {
                Body a = plain.getBody(i);
                Body b = sensed.getBody(i);
                assertEquals(Float.floatToIntBits(a.getX()), Float.floatToIntBits(b.getX()), "x of body " + i + " in tick " + t);
                assertEquals(Float.floatToIntBits(a.getY()), Float.floatToIntBits(b.getY()), "y of body " + i + " in tick " + t);
            }
        }
        assertTrue(falling.getY() > 1000f, "a dynamic sensor falls through the ground");
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4})
    void eventsTrackTheExactOverlapsABruteForceTestFinds(long seed) {
        World world = rain(seed, 40);
        Random random = new Random(seed);
        List<Body> sensors = new ArrayList<>();
        for (int k = 0; k < 3; k++) {
            Shape s = k == 0 ? Shape.createCircle(40f) : Shape.createPolygon(0f, -30f, 50f, 20f, -40f, 25f);
            Body sensor = new Body(-150f + 150f * k, -60f - 40f * k, s, k == 2);
            sensor.setSensor(true);
            world.addBody(sensor);
            sensors.add(sensor);
        }
        sensors.get(1).addCollisionLayer(3);
        world.getBody(5).addCollisionLayer(3);   // shares a layer with sensor 1: never its visitor
        List<TreeSet<Integer>> tracked = new ArrayList<>();
        for (int k = 0; k < 3; k++) {
            tracked.add(new TreeSet<>());
        }
        Collider collider = new Collider();
        Manifold scratch = new Manifold();
        int totalBegins = 0;
        for (int t = 0; t < 400; t++) {
            if (t == 150) {
                world.removeBody(world.getBody(7));
            }
            if (t == 250) {
                world.getBody(9).setPosition(-150f, -60f);
            }
            world.tick();
            StepData step = world.getStepData();
            for (int i = 0; i < step.getSensorEndCount(); i++) {
                int k = sensors.indexOf(step.getSensorEndSensor(i));
                assertTrue(tracked.get(k).remove(step.getSensorEndVisitor(i).getId()), "an end without a begin");
            }
            for (int i = 0; i < step.getSensorBeginCount(); i++) {
                int k = sensors.indexOf(step.getSensorBeginSensor(i));
                assertTrue(tracked.get(k).add(step.getSensorBeginVisitor(i).getId()), "a second begin");
                totalBegins++;
            }
            for (int k = 0; k < 3; k++) {
                Body sensor = sensors.get(k);
                TreeSet<Integer> brute = new TreeSet<>();
                for (int i = 0; i < world.getBodyCount(); i++) {
                    Body b = world.getBody(i);
                    if (b.isSensor() || (b.getCollisionLayers() & sensor.getCollisionLayers()) != 0) {
                        continue;
                    }
                    if (collider.overlaps(sensor.getShape(), sensor.getX(), sensor.getY(), sensor.getCos(), sensor.getSin(),
                            b.getShape(), b.getX(), b.getY(), b.getCos(), b.getSin(), scratch)) {
                        brute.add(b.getId());
                    }
                }
                assertEquals(brute, tracked.get(k), "sensor " + k + " after tick " + t);
            }
        }
        assertTrue(totalBegins >= 10, totalBegins + " sensor begins: the rain must cross the sensors");
        Body gone = sensors.get(0);
        int visitors = tracked.get(0).size();
        world.removeBody(gone);
        world.tick();
        StepData step = world.getStepData();
        int ended = 0;
        for (int i = 0; i < step.getSensorEndCount(); i++) {
            if (step.getSensorEndSensor(i) == gone) {
                ended++;
            }
        }
        assertEquals(visitors, ended, "a removed sensor ends all its overlaps, reported with the next tick");
    }

    @Test
    void aBallFallingThroughASensorBeginsAndEndsOnce() {
        World world = new World();
        world.setTicksPerSecond(60);
        Body sensor = new Body(0f, 0f, Shape.createRectangle(100f, 20f), false);
        sensor.setSensor(true);
        world.addBody(sensor);
        Body ball = new Body(0f, -100f, Shape.createCircle(5f), true);
        world.addBody(ball);
        int begins = 0;
        int ends = 0;
        for (int t = 0; t < 200; t++) {
            world.tick();
            StepData step = world.getStepData();
            for (int i = 0; i < step.getSensorBeginCount(); i++) {
                assertSame(ball, step.getSensorBeginVisitor(i));
                assertSame(sensor, step.getSensorBeginSensor(i));
                // The ball's bottom reached the sensor's top (y = −10) during this tick.
                assertTrue(ball.getY() + 5f >= -10f, "begins when overlapping");
                begins++;
            }
            ends += step.getSensorEndCount();
        }
        assertEquals(1, begins);
        assertEquals(1, ends);
    }
}
