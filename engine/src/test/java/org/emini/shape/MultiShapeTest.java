package org.emini.shape;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** A multi-shape's mass, centre of mass and inertia come from its parts by the parallel-axis theorem. */
class MultiShapeTest {
    private static final double REL = 1e-5;

    private static void assertClose(double expected, double actual) {
        assertEquals(expected, actual, REL * Math.abs(expected) + 1e-6);
    }

    /** A w × h rectangle centred at (cx, cy). */
    private static Polygon rect(float w, float h, float cx, float cy) {
        return Shape.createPolygon(cx - w / 2, cy - h / 2, cx + w / 2, cy - h / 2, cx + w / 2, cy + h / 2,
            cx - w / 2, cy + h / 2);
    }

    /** Σ m(w² + h²)/12 + m·d², written out independently of the shape code. */
    private static double rectInertia(double m, double w, double h, double cx, double cy) {
        return m * (w * w + h * h) / 12 + m * (cx * cx + cy * cy);
    }

    @Test
    void lShapeMassIsTheSumAndInertiaIsTheParallelAxisSum() {
        Polygon stem = rect(10f, 60f, 0f, -30f);
        Polygon foot = rect(40f, 10f, 15f, -5f);
        stem.setMass(2f);
        foot.setMass(3f);
        MultiShape l = new MultiShape(stem, foot);
        assertClose(5, l.getMass());
        assertClose((2 * 0 + 3 * 15) / 5.0, l.getCentroidX());
        assertClose((2 * -30 + 3 * -5) / 5.0, l.getCentroidY());
        assertClose(rectInertia(2, 10, 60, 0, -30) + rectInertia(3, 40, 10, 15, -5), l.getInertia());
        assertClose(1 / l.getInertia(), l.getInverseInertia());
        assertClose(600 + 400, l.getArea());
        assertEquals(Shape.TYPE_MULTI, l.getType());
        assertEquals(2, l.getShapeCount());
        assertSame(foot, l.getShape(1));
    }

    @Test
    void circlePartsAddHalfMassRadiusSquaredPlusOffsetTerm() {
        Circle a = new Circle(5f, 20f, 0f);
        Circle b = new Circle(5f, -20f, 0f);
        Polygon bar = rect(40f, 4f, 0f, 0f);
        MultiShape dumbbell = new MultiShape(a, b, bar);
        assertClose(3, dumbbell.getMass());
        assertClose(0, dumbbell.getCentroidX());
        double expected = 2 * (0.5 * 25 + 400) + rectInertia(1, 40, 4, 0, 0);
        assertClose(expected, dumbbell.getInertia());
        assertClose(25, dumbbell.getBoundingRadius());
    }

    @Test
    void settingTheMassScalesTheInertiaAndKeepsThePartsRatios() {
        MultiShape l = new MultiShape(rect(10f, 60f, 0f, -30f), rect(40f, 10f, 15f, -5f));
        double before = l.getInertia();
        l.setMass(8f);
        assertClose(8, l.getMass());
        assertClose(before * 4, l.getInertia());
    }

    @Test
    void centredMovesTheCentreOfMassToTheOriginAndLowersTheInertiaByMd2() {
        Polygon stem = rect(10f, 60f, 0f, -30f);
        stem.setMass(2f);
        MultiShape l = new MultiShape(stem, new Circle(8f, 30f, -8f));
        l.setFriction(0.6f);
        MultiShape c = l.centred();
        assertClose(0, c.getCentroidX());
        assertClose(0, c.getCentroidY());
        assertClose(l.getMass(), c.getMass());
        double d2 = l.getCentroidX() * l.getCentroidX() + l.getCentroidY() * l.getCentroidY();
        assertClose(l.getInertia() - l.getMass() * d2, c.getInertia());
        assertEquals(0.6f, c.getFriction());
        Circle moved = (Circle) c.getShape(1);
        assertClose(30 - l.getCentroidX(), moved.getCenterX());
    }

    @Test
    void theMaterialIsTheMultiShapesOwnNotTheParts() {
        Polygon part = rect(10f, 10f, 0f, 0f);
        part.setFriction(0.9f);
        part.setElasticity(0.7f);
        MultiShape m = Shape.createMultiShape(part);
        assertEquals(Shape.DEFAULT_FRICTION, m.getFriction());
        assertEquals(Shape.DEFAULT_ELASTICITY, m.getElasticity());
    }

    @Test
    void boundingBoxIsTheUnionOfTheParts() {
        MultiShape u = new MultiShape(rect(10f, 40f, -25f, 0f), rect(10f, 40f, 25f, 0f), rect(60f, 10f, 0f, 15f));
        float[] box = new float[4];
        u.computeAabb(100f, 50f, 1f, 0f, box);
        assertClose(70, box[0]);
        assertClose(30, box[1]);
        assertClose(130, box[2]);
        assertClose(70, box[3]);
        // A quarter turn: (x, y) → (−y, x).
        u.computeAabb(0f, 0f, 0f, 1f, box);
        assertClose(-20, box[0]);
        assertClose(-30, box[1]);
        assertClose(20, box[2]);
        assertClose(30, box[3]);
    }

    @Test
    void badPartsAreRefusedWithTheCallNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new MultiShape());
        assertTrue(e.getMessage().startsWith("MultiShape"));
        assertThrows(IllegalArgumentException.class, () -> new MultiShape((Shape[]) null));
        assertThrows(IllegalArgumentException.class, () -> new MultiShape(rect(1f, 1f, 0f, 0f), null));
        MultiShape inner = new MultiShape(rect(1f, 1f, 0f, 0f));
        e = assertThrows(IllegalArgumentException.class, () -> new MultiShape(inner));
        assertTrue(e.getMessage().contains("multi-shape"));
        assertThrows(IndexOutOfBoundsException.class, () -> inner.getShape(1));
    }
}
