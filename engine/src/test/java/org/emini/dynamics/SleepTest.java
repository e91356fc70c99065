package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.constraint.Joint;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * Sleeping: a settled pile falls asleep and costs no simulation, sleeps as one island, wakes as one
 * when touched or changed, and moves as the never-sleeping run does within the stacking tolerances.
 */
class SleepTest {
    private static World pyramidWorld(boolean sleeping, Body[][] out) {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setSleepingEnabled(sleeping);
        out[0] = Scenes.pyramid(world, 10, 20f);
        return world;
    }

    private static boolean allSleeping(Body[] bodies) {
        for (Body b : bodies) {
            if (!b.isSleeping()) {
                return false;
            }
        }
        return true;
    }

    @Test
    void aSettledPyramidSleepsAndASleepingOneCostsNoSimulation() {
        Body[][] boxes = new Body[1][];
        World world = pyramidWorld(true, boxes);
        int sleptAt = -1;
        for (int t = 0; t < 600 && sleptAt < 0; t++) {
            world.tick();
            if (allSleeping(boxes[0])) {
                sleptAt = t;
            }
        }
        // Built at rest, it rests from the start: asleep after the time to sleep (0.5 s, 30 ticks).
        assertTrue(sleptAt >= 29 && sleptAt < 300, "fell asleep at tick " + sleptAt);
        for (int t = 0; t < 100; t++) {
            world.tick();
            assertEquals(0, world.getSimulatedBodyCount());
            assertEquals(0, world.getStepData().getBodyCount());
        }
        assertTrue(allSleeping(boxes[0]));
    }

    @Test
    void aSleepingPyramidRestsWhereTheAwakeOneDoes() {
        Body[][] asleep = new Body[1][];
        Body[][] awake = new Body[1][];
        World a = pyramidWorld(true, asleep);
        World b = pyramidWorld(false, awake);
        for (int t = 0; t < 600; t++) {
            a.tick();
            b.tick();
        }
        assertTrue(allSleeping(asleep[0]));
        // Asleep, the soft contacts stop their slow creep (over 10 s the awake top box sinks 0.36 px
        // more and some boxes drift 0.1 px sideways, far below the sleep speed).
        for (int i = 0; i < asleep[0].length; i++) {
            assertEquals(awake[0][i].getX(), asleep[0][i].getX(), 0.25f, "x of box " + i);
            assertEquals(awake[0][i].getY(), asleep[0][i].getY(), 0.5f, "y of box " + i);
        }
    }

    @Test
    void aBallDroppedOnASleepingPyramidWakesItWithinATickAndMovesAsWithoutSleep() {
        Body[][] asleep = new Body[1][];
        Body[][] awake = new Body[1][];
        World a = pyramidWorld(true, asleep);
        World b = pyramidWorld(false, awake);
        for (int t = 0; t < 600; t++) {
            a.tick();
            b.tick();
        }
        // Dropped on the middle of the top box: an off-centre drop slides it by an amount that varies
        // by 0.6 px for a 0.05 px change of the drop point, awake or not.
        Body ballA = new Body(0f, -400f, Shape.createCircle(8f), true);
        Body ballB = new Body(0f, -400f, Shape.createCircle(8f), true);
        a.addBody(ballA);
        b.addBody(ballB);
        int touchedAt = -1;
        for (int t = 0; t < 400; t++) {
            a.tick();
            b.tick();
            boolean touching = false;
            for (int i = 0; i < a.getContactCount(); i++) {
                Contact c = a.getContact(i);
                touching |= c.getPointCount() > 0 && (c.getBodyA() == ballA || c.getBodyB() == ballA);
            }
            if (touching && touchedAt < 0) {
                touchedAt = t;
            }
            if (touchedAt >= 0 && t == touchedAt + 1) {
                assertFalse(asleep[0][asleep[0].length - 1].isSleeping(), "the top box woke");
                assertFalse(asleep[0][0].isSleeping(), "its island woke with it");
            }
        }
        assertTrue(touchedAt > 0);
        // Within the creep the awake pile had before the drop (above) and what it makes of the blow. The
        // awake top box has crept 0.1 px off centre by the drop, and the ball's end varies by 0.6 px per
        // 0.05 px of offset (measured: 0.49 px apart in float, 1.29 in double).
        assertEquals(ballB.getX(), ballA.getX(), 2f);
        assertEquals(ballB.getY(), ballA.getY(), 1f);
        for (int i = 0; i < asleep[0].length; i++) {
            assertEquals(awake[0][i].getX(), asleep[0][i].getX(), 1f, "x of box " + i);
            assertEquals(awake[0][i].getY(), asleep[0][i].getY(), 1f, "y of box " + i);
        }
    }

    @Test
    void islandsSleepAndWakeApart() {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setSleepingEnabled(true);
        Scenes.ground(world, 0f, 800f);
        Body[] left = stack(world, -200f);
        Body[] right = stack(world, 200f);
        Scenes.run(world, 5f);
        assertTrue(allSleeping(left) && allSleeping(right));
        left[0].applyImpulse(0f, -100f);
        assertFalse(left[2].isSleeping(), "an impulse wakes the whole stack");
        assertTrue(allSleeping(right), "the other stack sleeps on");
        Scenes.run(world, 5f);
        assertTrue(allSleeping(left));

        right[1].setVelocity(1f, 0f);
        assertFalse(right[0].isSleeping());
        Scenes.run(world, 5f);
        world.removeBody(right[0]);
        assertFalse(right[1].isSleeping(), "removing a body wakes what touched it");
        Scenes.run(world, 5f);
        assertTrue(allSleeping(new Body[] {right[1], right[2]}));

        world.addConstraint(Joint.atWorldPoint(left[2], right[2], 0f, -100f, false));
        assertFalse(left[0].isSleeping() || right[1].isSleeping(), "a joint wakes both islands");
        Scenes.run(world, 5f);
        world.setGravity(0f, 50f);
        assertFalse(left[1].isSleeping(), "new gravity wakes everything");
        left[1].setSleepingAllowed(false);
        Scenes.run(world, 5f);
        assertFalse(left[0].isSleeping(), "a body that may not sleep keeps its island awake");
        world.setSleepingEnabled(false);
        assertFalse(right[2].isSleeping(), "switching sleep off wakes all");
    }

    private static Body[] stack(World world, float x) {
        Shape box = Shape.createRectangle(20f, 20f);
        Body[] s = new Body[3];
        for (int i = 0; i < 3; i++) {
            s[i] = new Body(x, -10f - 20f * i, box, true);
            world.addBody(s[i]);
        }
        return s;
    }

    @Test
    void sleepingIsDeterministic() {
        Body[][] one = new Body[1][];
        Body[][] two = new Body[1][];
        World a = pyramidWorld(true, one);
        World b = pyramidWorld(true, two);
        for (int t = 0; t < 400; t++) {
            a.tick();
            b.tick();
            if (t == 200) {
                one[0][3].applyImpulse(30f, 0f);
                two[0][3].applyImpulse(30f, 0f);
            }
        }
        for (int i = 0; i < one[0].length; i++) {
            assertEquals(Float.floatToIntBits(one[0][i].getX()), Float.floatToIntBits(two[0][i].getX()));
            assertEquals(one[0][i].isSleeping(), two[0][i].isSleeping());
        }
    }

    @Test
    void aMovingKinematicPlatformKeepsItsLoadAwakeAndStartingItWakesThem() {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setSleepingEnabled(true);
        Body platform = new Body(0f, 0f, Shape.createRectangle(200f, 10f), false);
        platform.setKinematic(true);
        world.addBody(platform);
        Body box = new Body(0f, -15f, Shape.createRectangle(20f, 20f), true);
        world.addBody(box);
        platform.setVelocity(20f, 0f);
        Scenes.run(world, 3f);
        assertFalse(box.isSleeping(), "carried, it moves with the platform");
        assertFalse(platform.isSleeping());
        platform.setVelocity(0f, 0f);
        // The box slides on (friction 0.25 × 0.25 stops 20 px/s in 3.2 s), then both rest as one island.
        Scenes.run(world, 5f);
        assertTrue(box.isSleeping() && platform.isSleeping(), "both rest, as one island");
        platform.setVelocity(-20f, 0f);
        assertFalse(box.isSleeping(), "starting the platform wakes its load");
        float x = box.getX();
        // Friction takes it up to the platform's speed in 3.2 s (32 px), then it rides along.
        Scenes.run(world, 4f);
        assertTrue(box.getX() < x - 40f, "and carries it again: moved " + (box.getX() - x));
    }
}
