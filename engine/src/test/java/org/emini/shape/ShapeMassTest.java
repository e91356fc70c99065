package org.emini.shape;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Mass, inertia and area against closed forms. */
class ShapeMassTest {
    private static final double REL = 1e-5;

    private static void assertClose(double expected, double actual) {
        assertEquals(expected, actual, REL * Math.abs(expected) + 1e-9);
    }

    @Test
    void circleInertiaIsHalfMassTimesRadiusSquared() {
        Circle c = new Circle(10f);
        c.setMass(2f);
        assertClose(2 * 100 / 2.0, c.getInertia());
        assertClose(Math.PI * 100, c.getArea());
        assertClose(1 / 100.0, c.getInverseInertia());
    }

    @Test
    void offsetCircleAddsMassTimesOffsetSquared() {
        Circle c = new Circle(4f, 3f, 4f);
        c.setMass(2f);
        assertClose(2 * 16 / 2.0 + 2 * 25, c.getInertia());
        assertClose(3, c.getCentroidX());
        assertClose(4, c.getCentroidY());
        assertClose(9, c.getBoundingRadius());
    }

    @Test
    void twentyByTwentyBoxOfMassOneHasInertia66point67() {
        Polygon box = Shape.createRectangle(20f, 20f);
        assertClose(200.0 / 3.0, box.getInertia());
        assertClose(400, box.getArea());
    }

    @Test
    void rectangleInertiaIsMassTimesSumOfSquaresOverTwelve() {
        Polygon r = Shape.createRectangle(30f, 8f);
        r.setMass(3f);
        assertClose(3 * (30 * 30 + 8 * 8) / 12.0, r.getInertia());
        assertClose(1 / 3.0, r.getInverseMass());
    }

    @Test
    void regularPolygonInertiaMatchesTextbookFormula() {
        for (int n = 3; n <= Shape.MAX_VERTICES; n++) {
            Polygon p = Shape.createRegularPolygon(10f, n);
            p.setMass(2.5f);
            double cos = Math.cos(Math.PI / n);
            // I = m R² (1 + 2 cos²(π/n)) / 6; area = n R² sin(2π/n) / 2.
            assertClose(2.5 * 100 * (1 + 2 * cos * cos) / 6, p.getInertia());
            assertClose(n * 100 * Math.sin(2 * Math.PI / n) / 2, p.getArea());
        }
    }

    @Test
    void triangleAboutItsCentroidHasInertiaMassTimesSumOfSquaredSidesOver36() {
        // Vertices chosen so the centroid is the origin: (−4, −3), (8, −3), (−4, 6).
        Polygon t = Shape.createPolygon(-4f, -3f, 8f, -3f, -4f, 6f);
        t.setMass(1.5f);
        double a2 = 12 * 12;
        double b2 = 9 * 9;
        double c2 = 12 * 12 + 9 * 9;
        assertClose(0, t.getCentroidX());
        assertClose(0, t.getCentroidY());
        assertClose(1.5 * (a2 + b2 + c2) / 36, t.getInertia());
        assertClose(54, t.getArea());
    }

    @Test
    void offCentreTriangleFollowsParallelAxisTheorem() {
        Polygon t = Shape.createPolygon(1f, 2f, 7f, 3f, 2f, 9f);
        t.setMass(2f);
        double cx = (1 + 7 + 2) / 3.0;
        double cy = (2 + 3 + 9) / 3.0;
        double a2 = 6 * 6 + 1 * 1;
        double b2 = 5 * 5 + 6 * 6;
        double c2 = 1 * 1 + 7 * 7;
        assertClose(cx, t.getCentroidX());
        assertClose(cy, t.getCentroidY());
        assertClose(2 * (a2 + b2 + c2) / 36 + 2 * (cx * cx + cy * cy), t.getInertia());
    }

    @Test
    void offCentreRectangleFollowsParallelAxisTheorem() {
        Polygon r = Shape.createPolygon(10f, 20f, 40f, 20f, 40f, 30f, 10f, 30f);
        r.setMass(4f);
        assertClose(4 * (30 * 30 + 10 * 10) / 12.0 + 4 * (25 * 25 + 25 * 25), r.getInertia());
        assertClose(25, r.getCentroidX());
        assertClose(25, r.getCentroidY());
    }

    @Test
    void centredMovesCentroidToOriginAndRemovesParallelAxisTerm() {
        Polygon r = Shape.createPolygon(10f, 20f, 40f, 20f, 40f, 30f, 10f, 30f);
        r.setMass(4f);
        r.setFriction(0.7f);
        r.setElasticity(0.3f);
        Polygon c = r.centred();
        assertEquals(0, c.getCentroidX(), 1e-5);
        assertEquals(0, c.getCentroidY(), 1e-5);
        assertClose(r.getInertia() - 4 * (25 * 25 + 25 * 25), c.getInertia());
        assertEquals(4f, c.getMass());
        assertEquals(0.7f, c.getFriction());
        assertEquals(0.3f, c.getElasticity());
        assertClose(r.getArea(), c.getArea());
    }

    @Test
    void inertiaFollowsMassChanges() {
        Polygon box = Shape.createRectangle(20f, 20f);
        box.setMass(3f);
        assertClose(200.0, box.getInertia());
        assertClose(1 / 200.0, box.getInverseInertia());
        assertClose(1 / 3.0, box.getInverseMass());
    }

    @Test
    void boundingRadiusIsFarthestVertexFromOrigin() {
        assertClose(Math.sqrt(10 * 10 + 5 * 5), Shape.createRectangle(20f, 10f).getBoundingRadius());
        Polygon off = Shape.createPolygon(0f, 0f, 3f, 0f, 3f, 4f);
        assertClose(5, off.getBoundingRadius());
    }
}
