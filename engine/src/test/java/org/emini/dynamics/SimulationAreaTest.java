package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * Bodies outside the simulation area are frozen: they keep their state bit for bit, are not
 * simulated at all, and act as fixed obstacles for the bodies inside; moving the area wakes them.
 */
class SimulationAreaTest {
    /** A row of falling boxes at x = −500, −400, ..., 500 over a landscape floor at y = 0. */
    private static World row(Body[] out) {
        World world = new World();
        world.getLandscape().addSegment(-1000f, 0f, 1000f, 0f);
        Shape box = Shape.createRectangle(20f, 20f);
        for (int i = 0; i < out.length; i++) {
            out[i] = new Body(-500f + 100f * i, -200f, box, true);
            out[i].setVelocity(0f, 10f);
            out[i].setAngularVelocity(0.5f);
            world.addBody(out[i]);
        }
        return world;
    }

    @Test
    void bodiesOutsideTheAreaKeepTheirStateBitForBitAndAreNotSimulated() {
        Body[] boxes = new Body[11];
        World world = row(boxes);
        // x in [−150, 150]: boxes at −100, 0 and 100 are inside.
        world.setSimulationArea(-150f, -1000f, 150f, 1000f);
        assertTrue(world.hasSimulationArea());
        for (int t = 0; t < 80; t++) {
            world.tick();
        }
        assertEquals(3, world.getSimulatedBodyCount());
        for (Body b : boxes) {
            boolean inside = Math.abs(b.getX()) < 150f;
            if (inside) {
                assertEquals(-10f, b.getY(), 0.1f, "fell and rests on the floor");
            } else {
                assertEquals(-200f, b.getY(), "frozen");
                assertEquals(10f, b.getVelocityY(), "velocity kept");
                assertEquals(0.5f, b.getAngularVelocity(), "spin kept");
                assertEquals(0f, b.getAngle(), "not turned");
                assertEquals(0, b.getContactCount(), "never looked at the landscape");
            }
        }
    }

    @Test
    void movingTheAreaWakesFrozenBodiesWhichCarryOnFromTheirKeptState() {
        Body[] boxes = new Body[11];
        World world = row(boxes);
        world.setSimulationArea(-150f, -1000f, 150f, 1000f);
        for (int t = 0; t < 40; t++) {
            world.tick();
        }
        Body far = boxes[10];
        assertEquals(-200f, far.getY());
        float leftBehind = boxes[5].getY();
        // x in [250, 650]: the boxes at 300, 400 and 500.
        world.setSimulationArea(250f, -1000f, 650f, 1000f);
        world.tick();
        assertEquals(3, world.getSimulatedBodyCount());
        // One tick of free fall from the kept velocity, in n substeps of symplectic Euler:
        // v = 10 + g·dt, y = −200 + 10·dt + g·dt²·(n + 1)/(2n).
        float dt = world.getTimestep();
        int n = world.getConstraintIterations();
        assertEquals(10f + 100f * dt, far.getVelocityY(), 1e-4f);
        assertEquals(-200f + 10f * dt + 100f * dt * dt * (n + 1) / (2f * n), far.getY(), 1e-4f);
        for (int t = 0; t < 80; t++) {
            world.tick();
        }
        assertEquals(-10f, far.getY(), 0.1f);
        assertEquals(-200f, boxes[0].getY(), "never inside");
        assertEquals(leftBehind, boxes[5].getY(), "frozen where the area left it");
        world.clearSimulationArea();
        assertFalse(world.hasSimulationArea());
        world.tick();
        assertEquals(boxes.length, world.getSimulatedBodyCount());
    }

    @Test
    void aBodyWhoseBoxOverlapsTheAreaEdgeIsInside() {
        World world = new World();
        Body edge = new Body(105f, 0f, Shape.createRectangle(20f, 20f), true);
        Body out = new Body(111f, 0f, Shape.createRectangle(20f, 20f), true);
        world.addBody(edge);
        world.addBody(out);
        world.setSimulationArea(-100f, -100f, 100f, 100f);
        world.tick();
        assertTrue(edge.getY() > 0f, "box from x 95 to 115 overlaps the area");
        assertEquals(0f, out.getY(), "box from x 101 to 121 does not");
    }

    /** Frozen bodies are obstacles: a box inside lands on a frozen box and rests on it. */
    @Test
    void bodiesInsideRestOnFrozenBodies() {
        World world = new World();
        world.getLandscape().addSegment(-100f, 0f, 100f, 0f);
        Body frozen = new Body(0f, -60f, Shape.createRectangle(40f, 20f), true);
        world.addBody(frozen);
        Body falling = new Body(0f, -200f, Shape.createRectangle(20f, 20f), true);
        world.addBody(falling);
        // The area ends at y = −71: the frozen box (y from −70 to −50) is outside.
        world.setSimulationArea(-100f, -1000f, 100f, -71f);
        for (int t = 0; t < 100; t++) {
            world.tick();
        }
        assertEquals(-60f, frozen.getY(), "frozen in the air");
        assertEquals(-80f, falling.getY(), 0.1f, "rests on the frozen box");
        assertEquals(0f, falling.getVelocityY(), 0.5f);
        assertEquals(1, world.getSimulatedBodyCount());
    }

    /** Forces applied while a body is frozen do not pile up and hit it when it wakes. */
    @Test
    void forcesAppliedToAFrozenBodyDoNotAccumulate() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body b = new Body(500f, 0f, Shape.createCircle(5f), true);
        world.addBody(b);
        world.setSimulationArea(-10f, -10f, 10f, 10f);
        for (int t = 0; t < 50; t++) {
            b.applyForce(100f, 0f);
            world.tick();
        }
        assertEquals(0f, b.getVelocityX());
        world.clearSimulationArea();
        b.applyForce(100f, 0f);
        world.tick();
        assertEquals(100f * world.getTimestep(), b.getVelocityX(), 1e-4f, "one tick of force");
    }

    /** An area that holds every body changes nothing: the results are bit-identical. */
    @Test
    void anAreaHoldingEveryBodyGivesBitIdenticalResults() {
        World plain = DeterminismTest.rain(11);
        World bounded = DeterminismTest.rain(11);
        bounded.setSimulationArea(-5000f, -5000f, 5000f, 5000f);
        for (int t = 0; t < 200; t++) {
            plain.tick();
            bounded.tick();
        }
        assertEquals(DeterminismTest.hash(plain), DeterminismTest.hash(bounded));
        assertEquals(plain.getSimulatedBodyCount(), bounded.getSimulatedBodyCount());
    }

    @Test
    void theOriginalsXRangeSpansTheFullHeight() {
        World world = new World();
        Body inside = new Body(0f, -1e4f, Shape.createCircle(5f), true);
        Body outside = new Body(300f, 0f, Shape.createCircle(5f), true);
        world.addBody(inside);
        world.addBody(outside);
        world.setSimulationArea(-100f, 100f);
        world.tick();
        assertTrue(inside.getY() > -1e4f);
        assertEquals(0f, outside.getY());
        assertEquals(-100f, world.getSimulationAreaMinX());
        assertEquals(100f, world.getSimulationAreaMaxX());
    }

    @Test
    void badAreasAreRefusedWithTheCallNamed() {
        World world = new World();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> world.setSimulationArea(10f, 0f, 0f, 10f));
        assertTrue(e.getMessage().contains("World.setSimulationArea"));
        assertThrows(IllegalArgumentException.class, () -> world.setSimulationArea(0f, Float.NaN, 1f, 1f));
        assertFalse(world.hasSimulationArea());
    }
}
