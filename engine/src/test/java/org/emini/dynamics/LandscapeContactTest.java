package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Bodies against the landscape: resting, sliding, bouncing, materials, filters and edits. */
class LandscapeContactTest {
    private static final float G = 100f;

    private static Body drop(World world, Shape shape, float x, float y) {
        Body b = new Body(x, y, shape, true);
        world.addBody(b);
        return b;
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"box", "circle", "hexagon"})
    void bodyRestsOnALandscapeFloorAtItsHalfHeight(String kind) {
        World world = new World();
        world.getLandscape().addSegment(-500f, 0f, 500f, 0f);
        Shape shape = kind.equals("box") ? Shape.createRectangle(20f, 20f)
            : kind.equals("circle") ? Shape.createCircle(10f) : Shape.createRegularPolygon(10f, 6);
        float half = kind.equals("hexagon") ? 10f * (float) Math.sin(Math.PI / 3) : 10f;
        Body b = drop(world, shape, 0f, -60f);
        // The same drop onto a static ground body: the landscape floor must behave the same.
        World reference = new World();
        Scenes.ground(reference, 0f, 1000f);
        Body r = drop(reference, shape, 0f, -60f);
        Scenes.run(world, 4f);
        Scenes.run(reference, 4f);
        assertEquals(-half, b.getY(), 0.1f);
        assertEquals(0f, b.getVelocityY(), 0.5f);
        assertEquals(r.getX(), b.getX(), 0.01f);
        assertEquals(r.getY(), b.getY(), 0.01f);
        assertEquals(r.getAngle(), b.getAngle(), 1e-4f);
    }

    /** Places a 20 px box at rest on a landscape slope through the origin; θ grows clockwise. */
    private static Body slope(World world, float degrees, float boxFriction, float landscapeFriction) {
        float theta = (float) Math.toRadians(degrees);
        float c = (float) Math.cos(theta);
        float s = (float) Math.sin(theta);
        world.getLandscape().addSegment(-2000f * c, -2000f * s, 2000f * c, 2000f * s);
        world.getLandscape().setFriction(landscapeFriction);
        Shape box = Shape.createRectangle(20f, 20f);
        box.setFriction(boxFriction);
        // 10 px above the slope along its upper normal (s, −c), 300 px up the slope.
        Body b = new Body(-300f * c + 10f * s, -300f * s - 10f * c, box, true);
        b.setAngle(theta);
        world.addBody(b);
        return b;
    }

    private static float along(float x, float y, float theta) {
        return (float) (x * Math.cos(theta) + y * Math.sin(theta));
    }

    @ParameterizedTest(name = "{0}° box μ {1} landscape μ {2}")
    @CsvSource({"30, 0.2, 1", "30, 1, 0.2", "45, 0.5, 1", "30, 0, 1", "35, 0.8, 0.5"})
    void boxSlidesDownALandscapeSlopeWithClosedFormAcceleration(float degrees, float boxMu, float landMu) {
        World world = new World();
        Body b = slope(world, degrees, boxMu, landMu);
        float theta = (float) Math.toRadians(degrees);
        Scenes.run(world, 0.5f);
        float v0 = along(b.getVelocityX(), b.getVelocityY(), theta);
        Scenes.run(world, 2f);
        float v1 = along(b.getVelocityX(), b.getVelocityY(), theta);
        double mu = boxMu * landMu;
        double expected = G * (Math.sin(theta) - mu * Math.cos(theta));
        assertEquals(expected, (v1 - v0) / 2.0, 0.03 * expected, "a = g(sin θ − μ cos θ)");
        assertEquals(theta, b.getAngle(), 0.01f, "slides without tipping");
    }

    @ParameterizedTest(name = "{0}° box μ {1} landscape μ {2}")
    @CsvSource({"20, 0.5, 1", "30, 1, 0.7", "10, 0.5, 0.5"})
    void boxSticksOnALandscapeSlopeWhenTanThetaIsBelowMu(float degrees, float boxMu, float landMu) {
        World world = new World();
        Body b = slope(world, degrees, boxMu, landMu);
        float theta = (float) Math.toRadians(degrees);
        Scenes.run(world, 0.5f);
        float start = along(b.getX(), b.getY(), theta);
        Scenes.run(world, 5f);
        assertEquals(start, along(b.getX(), b.getY(), theta), 0.5f, "tan θ < μ: the box stays");
    }

    @Test
    void contactMaterialIsTheShapesFactorTimesTheLandscapes() {
        World world = new World();
        world.getLandscape().addSegment(-100f, 0f, 100f, 0f);
        world.getLandscape().setFriction(0.5f);
        world.getLandscape().setElasticityPercent(40);
        Shape box = Shape.createRectangle(20f, 20f);
        box.setFriction(0.8f);
        box.setElasticity(0.5f);
        Body b = drop(world, box, 0f, -10f);
        world.tick();
        assertEquals(1, b.getContactCount());
        Contact[] cs = new Contact[1];
        b.getContacts(cs);
        assertEquals(0.4f, cs[0].getFriction(), 1e-6f);
        assertEquals(0.2f, cs[0].getElasticity(), 1e-6f);
    }

    @Test
    void ballBouncesOffTheLandscapeWithTheElasticityProduct() {
        World world = new World();
        world.setTicksPerSecond(60f);
        world.setGravity(0f, 0f);
        world.getLandscape().addSegment(-100f, 0f, 100f, 0f);
        world.getLandscape().setElasticity(0.8f);
        Shape ball = Shape.createCircle(10f);
        ball.setElasticity(0.75f);
        Body b = drop(world, ball, 0f, -50f);
        b.setVelocity(0f, 200f);
        Scenes.run(world, 1f);
        assertEquals(-0.6f * 200f, b.getVelocityY(), 2f, "e = 0.75 × 0.8");
    }

    @Test
    void landscapeContactShowsInTheBodysContactsWithTheSegmentAndNoBodyB() {
        World world = new World();
        Landscape l = world.getLandscape();
        l.addSegment(-300f, 50f, -200f, 50f);
        int floor = l.addSegment(-100f, 0f, 100f, 0f);
        Body b = drop(world, Shape.createRectangle(20f, 20f), 0f, -10f);
        Scenes.run(world, 0.5f);
        assertEquals(1, b.getContactCount());
        Contact[] cs = new Contact[2];
        assertEquals(1, b.getContacts(cs));
        Contact c = cs[0];
        assertTrue(c.isLandscape());
        assertEquals(floor, c.getSegment());
        assertEquals(b, c.getBodyA());
        assertNull(c.getBodyB());
        assertNull(c.getOther(b));
        assertEquals(2, c.getPointCount());
        assertEquals(0f, c.getNormalX(), 1e-6f);
        assertEquals(1f, c.getNormalY(), 1e-6f, "from the body to the landscape");
        assertEquals(1f * G * 0.05f / 10, c.getNormalImpulse(0) + c.getNormalImpulse(1), 0.02f,
            "the contact carries the weight: m·g·h per substep");
        assertTrue(world.getContactCount() >= 1);
        // Removing the other segment shifts the floor's index.
        l.removeSegment(0);
        world.tick();
        assertEquals(floor - 1, c.getSegment());
    }

    /** The original's filter: layers and the interacting flag do not matter; static bodies ignore it. */
    @Test
    void landscapeIgnoresLayersAndTheInteractingFlagAndStaticBodies() {
        World world = new World();
        world.getLandscape().addSegment(-300f, 0f, 300f, 0f);
        Body layered = drop(world, Shape.createRectangle(20f, 20f), -100f, -30f);
        layered.addCollisionLayer(3);
        Body ghost = drop(world, Shape.createCircle(10f), 100f, -30f);
        ghost.setInteracting(false);
        Body fixed = new Body(0f, 0f, Shape.createRectangle(40f, 40f), false);
        world.addBody(fixed);
        Scenes.run(world, 2f);
        assertEquals(-10f, layered.getY(), 0.1f);
        assertEquals(-10f, ghost.getY(), 0.1f);
        assertEquals(0, fixed.getContactCount());
    }

    @Test
    void bodyBecomingStaticLosesItsLandscapeContactsAndRegainsThemWhenDynamic() {
        World world = new World();
        world.getLandscape().addSegment(-300f, 0f, 300f, 0f);
        Body b = drop(world, Shape.createRectangle(20f, 20f), 0f, -10f);
        Scenes.run(world, 0.5f);
        assertEquals(1, b.getContactCount());
        b.setDynamic(false);
        world.tick();
        assertEquals(0, b.getContactCount());
        b.setDynamic(true);
        b.setPosition(0f, -10f);
        Scenes.run(world, 1f);
        assertEquals(1, b.getContactCount());
        assertEquals(-10f, b.getY(), 0.1f);
    }

    @Test
    void removingTheSegmentUnderABodyLetsItFallAndAddingOneCatchesIt() {
        World world = new World();
        Landscape l = world.getLandscape();
        l.addSegment(-300f, 0f, 300f, 0f);
        Body b = drop(world, Shape.createRectangle(20f, 20f), 0f, -10f);
        Scenes.run(world, 1f);
        assertEquals(-10f, b.getY(), 0.1f);
        l.removeSegment(0);
        Scenes.run(world, 1f);
        assertTrue(b.getY() > 20f, "falls once its floor is gone: y " + b.getY());
        l.addSegment(-300f, 200f, 300f, 200f);
        Scenes.run(world, 4f);
        assertEquals(190f, b.getY(), 0.1f);
        assertEquals(0f, b.getVelocityY(), 0.5f);
    }

    @Test
    void replacingTheLandscapeDropsTheOldContacts() {
        World world = new World();
        world.getLandscape().addSegment(-300f, 0f, 300f, 0f);
        Body b = drop(world, Shape.createCircle(10f), 0f, -10f);
        Scenes.run(world, 0.5f);
        Landscape lower = new Landscape();
        lower.addSegment(-300f, 100f, 300f, 100f);
        world.setLandscape(lower);
        assertTrue(world.getLandscape() == lower);
        Scenes.run(world, 4f);
        assertEquals(90f, b.getY(), 0.1f);
        assertEquals(1, b.getContactCount());
    }

    /**
     * A frictionless floor made of many short segments, given in scrambled order and directions,
     * is as smooth as one segment: a sliding box and a rolling ball keep their speed, height and
     * angle across the joints (no catching on the segments' ends).
     */
    @ParameterizedTest(name = "{0}")
    @CsvSource({"box", "circle"})
    void bodySlidesAcrossTheJointsOfAChainOfSegmentsWithoutCatching(String kind) {
        World world = new World();
        world.setTicksPerSecond(60f);
        Landscape l = world.getLandscape();
        l.setFriction(0f);
        int n = 300;
        Random random = new Random(5);
        int[] perm = new int[n];
        for (int i = 0; i < n; i++) {
            perm[i] = i;
        }
        for (int i = n - 1; i > 0; i--) {
            int j = random.nextInt(i + 1);
            int t = perm[i];
            perm[i] = perm[j];
            perm[j] = t;
        }
        for (int k = 0; k < n; k++) {
            float x0 = -1500f + perm[k] * 10f;
            if (random.nextBoolean()) {
                l.addSegment(x0, 0f, x0 + 10f, 0f);
            } else {
                l.addSegment(x0 + 10f, 0f, x0, 0f);
            }
        }
        Shape shape = kind.equals("box") ? Shape.createRectangle(20f, 20f) : Shape.createCircle(10f);
        Body b = drop(world, shape, -1400f, -10f);
        Scenes.run(world, 0.5f);
        b.setVelocity(300f, 0f);
        float x0 = b.getX();
        for (int t = 0; t < 480; t++) {
            world.tick();
            assertEquals(300f, b.getVelocityX(), 0.5f, "tick " + t);
            assertEquals(-10f, b.getY(), 0.1f, "tick " + t);
            assertEquals(0f, b.getVelocityY(), 1f, "tick " + t);
        }
        assertEquals(x0 + 300f * 8f, b.getX(), 1f);
        if (kind.equals("box")) {
            assertEquals(0f, b.getAngle(), 1e-3f);
        }
    }

    /**
     * At a convex corner (a ledge) a box slides off and tips over the edge; at a concave corner it
     * stops against the wall. Joints do not hide real corners.
     */
    @Test
    void realCornersStillStopAndTipBodies() {
        World world = new World();
        Landscape l = world.getLandscape();
        l.setFriction(0f);
        // A floor ending in a wall on the right, at x = 100.
        l.addSegment(-200f, 0f, 100f, 0f);
        l.addSegment(100f, 0f, 100f, -100f);
        Body box = drop(world, Shape.createRectangle(20f, 20f), 0f, -10f);
        box.setVelocity(100f, 0f);
        float reached = 0f;
        for (int t = 0; t < 60; t++) {
            world.tick();
            reached = Math.max(reached, box.getX());
        }
        assertEquals(90f, reached, 0.05f, "stopped by the wall");
        assertTrue(box.getX() > 85f, "and stays there: x " + box.getX());
        // A ledge: the floor ends at x = 100 and drops away.
        World ledge = new World();
        ledge.getLandscape().addSegment(-200f, 0f, 100f, 0f);
        ledge.getLandscape().addSegment(100f, 0f, 100f, 300f);
        ledge.getLandscape().addSegment(100f, 300f, 400f, 300f);
        Body b = drop(ledge, Shape.createRectangle(20f, 20f), 50f, -10f);
        b.setVelocity(60f, 0f);
        Scenes.run(ledge, 6f);
        assertEquals(290f, b.getY(), 0.3f, "fell off the ledge onto the lower floor");
        assertTrue(b.getX() > 100f);
    }

    @Test
    void badSegmentsAreRefusedWithTheCallNamed() {
        Landscape l = new Landscape();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> l.addSegment(0f, 0f, Float.NaN, 1f));
        assertTrue(e.getMessage().contains("Landscape.addSegment"));
        e = assertThrows(IllegalArgumentException.class, () -> l.addSegment(0f, 0f, 1f, 1f, 3));
        assertTrue(e.getMessage().contains("face"));
        assertThrows(IndexOutOfBoundsException.class, () -> l.removeSegment(0));
        assertThrows(IllegalArgumentException.class, () -> l.setFriction(1.5f));
        assertThrows(IllegalArgumentException.class, () -> new World().setLandscape(null));
    }

    @Test
    void zeroLengthSegmentsLoadAndStopNothing() {
        World world = new World();
        world.getLandscape().addSegment(0f, 0f, 0f, 0f);
        Body b = drop(world, Shape.createCircle(5f), 0f, -20f);
        Scenes.run(world, 1f);
        assertTrue(b.getY() > 20f);
    }

    @Test
    void copiedLandscapeHasTheSameSegmentsAndMaterial() {
        Landscape l = new Landscape();
        l.addSegment(0f, 0f, 10f, 5f, Landscape.FACE_LEFT);
        l.addSegment(10f, 5f, 20f, 0f, Landscape.FACE_RIGHT);
        l.setFriction(0.7f);
        l.setElasticity(0.1f);
        Landscape copy = new Landscape(l);
        assertEquals(2, copy.getSegmentCount());
        for (int i = 0; i < 2; i++) {
            assertEquals(l.getStartX(i), copy.getStartX(i));
            assertEquals(l.getEndY(i), copy.getEndY(i));
            assertEquals(l.getFace(i), copy.getFace(i));
        }
        assertEquals(0.7f, copy.getFriction());
        assertEquals(0.1f, copy.getElasticity());
    }
}
