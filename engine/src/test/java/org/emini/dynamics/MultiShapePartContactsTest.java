package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * Each part of a multi-shape has its own broadphase proxy, so a body meets only the parts it is near:
 * a ball in a hollow box has a contact with the wall under it, not with all four, whether the box
 * stands or turns; a part's box is stretched along its own motion, so the head of a turning hammer
 * meets what lies in its path; a part meets the landscape alone; contacts begin and end per pair of
 * parts; and a body whose shape changes between one part and several keeps colliding.
 */
class MultiShapePartContactsTest {
    // The tumbler's box (scenarios/bench/tumbler.yaml): walls 20 px thick around a 500 x 500 interior.
    private static final int TOP = 0;
    private static final int BOTTOM = 1;
    private static final int LEFT = 2;
    private static final int RIGHT = 3;

    private static Polygon rect(float cx, float cy, float w, float h) {
        return Shape.createPolygon(cx - w / 2, cy - h / 2, cx + w / 2, cy - h / 2, cx + w / 2, cy + h / 2, cx - w / 2,
            cy + h / 2);
    }

    /** The four walls, in the order TOP, BOTTOM, LEFT, RIGHT (y grows downwards). */
    private static MultiShape hollowBox() {
        return new MultiShape(rect(0f, -260f, 540f, 20f), rect(0f, 260f, 540f, 20f), rect(-260f, 0f, 20f, 500f),
            rect(260f, 0f, 20f, 500f));
    }

    /** The body's only contact. */
    private static Contact onlyContact(Body b) {
        Contact[] out = new Contact[1];
        assertEquals(1, b.getContacts(out), "contacts of " + b);
        return out[0];
    }

    private static int partOfBox(Contact c, Body box) {
        return c.getBodyA() == box ? c.getPartA() : c.getPartB();
    }

    @Test
    void aBallOnTheFloorOfAHollowBoxMeetsTheFloorAloneAndOneInTheMiddleNothing() {
        World world = new World();
        Body box = new Body(0f, 0f, hollowBox(), false);
        world.addBody(box);
        Body resting = new Body(0f, 240f, Shape.createCircle(5f), true);
        Body floating = new Body(0f, 0f, Shape.createCircle(5f), true);
        floating.setGravityAffected(false);
        world.addBody(resting);
        world.addBody(floating);
        Scenes.run(world, 2f);
        assertEquals(250f - 5f, resting.getY(), 0.5f, "resting on the floor");
        assertEquals(1, resting.getContactCount(), "one contact: the floor (one proxy for the box made four)");
        assertEquals(BOTTOM, partOfBox(onlyContact(resting), box));
        assertEquals(0, floating.getContactCount(), "no wall near the middle");
        assertEquals(1, world.getContactCount());
    }

    /**
     * A small tumbler: 64 balls in the box turning at 2 rad/s. Every contact of a ball with the box is
     * with a wall within a few pixels of it (the fat boxes' margins and stretch), so there are fewer
     * than two per ball, not four; the pile still stays inside.
     */
    @Test
    void ballsInATurningBoxHaveContactsOnlyWithTheWallsNearThem() {
        World world = new World();
        world.setTicksPerSecond(60);
        Body box = new Body(0f, 0f, hollowBox(), false);
        box.setKinematic(true);
        box.setAngularVelocity(2f);
        world.addBody(box);
        List<Body> balls = new ArrayList<>();
        Shape ball = Shape.createCircle(5f);
        for (int i = 0; i < 64; i++) {
            Body b = new Body(-200f + 50f * (i % 8), -200f + 50f * (i / 8), ball, true);
            world.addBody(b);
            balls.add(b);
        }
        MultiShape walls = (MultiShape) box.getShape();
        int most = 0;
        for (int t = 0; t < 300; t++) {
            world.tick();
            int withBox = 0;
            for (int i = 0; i < world.getContactCount(); i++) {
                Contact c = world.getContact(i);
                if (c.getBodyA() != box && c.getBodyB() != box) {
                    continue;
                }
                withBox++;
                Body b = c.getBodyA() == box ? c.getBodyB() : c.getBodyA();
                float gap = gapToPart(walls.getShape(partOfBox(c, box)), box, b);
                assertTrue(gap < 100f, "tick " + t + ": a contact with wall " + partOfBox(c, box) + " " + gap
                    + " px from the ball");
            }
            most = Math.max(most, withBox);
        }
        assertTrue(most < 2 * balls.size(), "contacts with the box at most " + most + " (one proxy: 4 per ball)");
        for (Body b : balls) {
            assertTrue(Math.hypot(b.getX(), b.getY()) < 360f, "inside: " + b);
        }
    }

    /**
     * The distance from the ball's surface to the part's bounding box where the box is now (0 when they
     * overlap). A contact lives while the two fat boxes overlap: their margins and their stretch along
     * each one's motion (at 2 rad/s a wall's centre moves 8.7 px a tick, and the balls about as much,
     * each stretched fourfold) keep it under 100 px; with one proxy for the box it reached 490.
     */
    private static float gapToPart(Shape part, Body box, Body ball) {
        float[] aabb = new float[4];
        part.computeAabb(box.getX(), box.getY(), (float) Math.cos(box.getAngle()), (float) Math.sin(box.getAngle()),
            aabb);
        float ox = Math.max(0f, Math.max(aabb[0] - ball.getX(), ball.getX() - aabb[2]));
        float oy = Math.max(0f, Math.max(aabb[1] - ball.getY(), ball.getY() - aabb[3]));
        return Math.max(0f, (float) Math.hypot(ox, oy) - 5f);
    }

    /**
     * A hammer turning at 10 and 15 rad/s about its handle's end: its head (200 px out) moves 33 and
     * 50 px a tick while the body's centre stands still. The head's proxy is stretched by the head's
     * own velocity, so the pair with a ball in its path exists before the head arrives and the
     * speculative contact stops it at the surface: measured 2.1 and 3.3 px deep, where a box
     * stretched by the body's velocity (zero) let it sink 5.6 and 7.1 px.
     */
    @Test
    void aTurningHammersHeadMeetsABallInItsPath() {
        for (float omega : new float[] {10f, 15f}) {
            World world = new World();
            world.setTicksPerSecond(60);
            MultiShape hammer = new MultiShape(rect(92.5f, 0f, 185f, 4f), rect(200f, 0f, 30f, 20f));
            Body body = new Body(0f, 0f, hammer, true);
            body.setKinematic(true);
            body.setAngularVelocity(omega);
            world.addBody(body);
            // 60 degrees ahead of the head.
            Body ball = new Body(100f, 173.2f, Shape.createCircle(5f), true);
            ball.setGravityAffected(false);
            world.addBody(ball);
            float deepest = 0f;
            for (int t = 0; t < 30; t++) {
                world.tick();
                float c = (float) Math.cos(body.getAngle());
                float s = (float) Math.sin(body.getAngle());
                float lx = c * ball.getX() + s * ball.getY();
                float ly = -s * ball.getX() + c * ball.getY();
                // The ball's overlap with the head (15 x 10 px half-extents, grown by the radius).
                if (lx >= 180f && lx <= 220f) {
                    deepest = Math.max(deepest, Math.min(15f - Math.abs(ly), 20f - Math.abs(lx - 200f)));
                }
            }
            assertTrue(Math.hypot(ball.getVelocityX(), ball.getVelocityY()) > 1000f, "hit at " + omega + " rad/s");
            assertTrue(deepest < 4f, "the head sank " + deepest + " px into the ball at " + omega + " rad/s");
        }
    }

    /** An L standing on its foot on the landscape: the foot touches, the stem (10 px up) has no contact. */
    @Test
    void eachPartMeetsTheLandscapeAlone() {
        World world = new World();
        world.getLandscape().addSegment(-1000f, 0f, 1000f, 0f);
        MultiShape l = new MultiShape(rect(5f, -35f, 10f, 50f), rect(20f, -5f, 40f, 10f)).centred();
        Body b = new Body(0f, 0f, l, true);
        world.addBody(b);
        // Its centred frame: put the foot's bottom on the floor.
        float[] aabb = new float[4];
        l.computeAabb(0f, 0f, 1f, 0f, aabb);
        b.setPosition(0f, -aabb[3]);
        Scenes.run(world, 2f);
        assertEquals(1, b.getContactCount(), "the foot's contact alone (one proxy for the body made two)");
        Contact c = onlyContact(b);
        assertTrue(c.isLandscape());
        assertEquals(1, c.getPartA(), "the foot");
        assertTrue(c.isTouching());
    }

    /**
     * Gravity tilted towards the bottom-right corner rolls a ball into it: contacts begin with the
     * floor and the right wall. Tilted the other way, the ball leaves the right wall (one end, while
     * the floor contact stays) and rolls into the other corner, where a contact with the left wall
     * begins. The ball never has more contacts than the walls it is near (one proxy for the box made four).
     */
    @Test
    void contactsBeginAndEndPerPairOfParts() {
        World world = new World();
        world.setTicksPerSecond(60);
        Body box = new Body(0f, 0f, hollowBox(), false);
        world.addBody(box);
        Body ball = new Body(0f, 240f, Shape.createCircle(5f), true);
        world.addBody(ball);
        world.setGravity(100f, 100f);
        List<Integer> began = new ArrayList<>();
        int ends = run(world, 3f, box, ball, began);
        assertTrue(began.contains(BOTTOM) && began.contains(RIGHT), "begins " + began);
        assertEquals(setOf(BOTTOM, RIGHT), touchedParts(ball, box));
        began.clear();
        world.setGravity(-100f, 100f);
        ends = run(world, 1f, box, ball, began);
        assertEquals(1, ends, "the right wall's contact ended");
        assertEquals(setOf(BOTTOM), touchedParts(ball, box), "rolling on the floor");
        ends = run(world, 5f, box, ball, began);
        // The blow on the left wall may lift the ball off the floor for a moment: that contact ends and
        // begins again; every other begin is the left wall's.
        assertEquals(LEFT, (int) began.get(0), "begins " + began);
        assertTrue(!began.contains(TOP) && !began.contains(RIGHT), "begins " + began);
        assertEquals(began.size() - 1, ends, "begins " + began);
        assertEquals(setOf(BOTTOM, LEFT), touchedParts(ball, box));
    }

    /** Ticks for some seconds, noting the parts of the box whose contacts begin; returns the ends. */
    private static int run(World world, float seconds, Body box, Body ball, List<Integer> began) {
        int ends = 0;
        for (int t = 0; t < (int) Math.round(seconds / world.getTimestep()); t++) {
            world.tick();
            StepData step = world.getStepData();
            for (int i = 0; i < step.getBeginCount(); i++) {
                began.add(partOfBox(step.getBeginContact(i), box));
            }
            ends += step.getEndCount();
            assertTrue(ball.getContactCount() <= 2, "contacts " + ball.getContactCount());
        }
        return ends;
    }

    private static java.util.Set<Integer> setOf(Integer... parts) {
        return new java.util.TreeSet<>(java.util.Arrays.asList(parts));
    }

    /** The parts of the box that the ball's touching contacts are with. */
    private static java.util.Set<Integer> touchedParts(Body ball, Body box) {
        Contact[] out = new Contact[8];
        java.util.Set<Integer> parts = new java.util.TreeSet<>();
        for (int i = 0, n = ball.getContacts(out); i < n; i++) {
            if (out[i].isTouching()) {
                parts.add(partOfBox(out[i], box));
            }
        }
        return parts;
    }

    /** A box's shape changes from four walls to one plate and back under a resting ball, which stays on it. */
    @Test
    void aShapeChangeBetweenOneAndSeveralPartsKeepsColliding() {
        World world = new World();
        Body box = new Body(0f, 0f, hollowBox(), false);
        world.addBody(box);
        Body ball = new Body(0f, 240f, Shape.createCircle(5f), true);
        world.addBody(ball);
        Scenes.run(world, 1f);
        box.setShape(rect(0f, 260f, 540f, 20f));
        Scenes.run(world, 1f);
        assertEquals(245f, ball.getY(), 0.5f, "on the plate");
        assertEquals(1, ball.getContactCount());
        assertEquals(0, onlyContact(ball).getPartA() + onlyContact(ball).getPartB(), "the plate is part 0");
        box.setShape(hollowBox());
        Scenes.run(world, 1f);
        assertEquals(245f, ball.getY(), 0.5f, "on the floor again");
        assertEquals(1, ball.getContactCount());
        assertEquals(BOTTOM, partOfBox(onlyContact(ball), box));
    }
}
