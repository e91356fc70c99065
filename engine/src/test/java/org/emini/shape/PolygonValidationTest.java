package org.emini.shape;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.InvalidShapeException.Rule;
import org.junit.jupiter.api.Test;

/** Each validation rule of {@link Polygon}, and the cleaning steps. */
class PolygonValidationTest {
    private static InvalidShapeException refused(Rule rule, float... xy) {
        InvalidShapeException e = assertThrows(InvalidShapeException.class, () -> new Polygon(xy));
        assertEquals(rule, e.getRule(), e.getMessage());
        assertTrue(e.getMessage().contains(rule.name()), e.getMessage());
        return e;
    }

    private static void assertNamesVertex(InvalidShapeException e, int index, String coords) {
        assertEquals(index, e.getVertexIndex(), e.getMessage());
        assertTrue(e.getMessage().contains("vertex " + index + " at " + coords), e.getMessage());
    }

    private static double signedArea(Polygon p) {
        double a = 0;
        int n = p.getVertexCount();
        for (int i = 0; i < n; i++) {
            int k = (i + 1) % n;
            a += p.getVertexX(i) * p.getVertexY(k) - p.getVertexX(k) * p.getVertexY(i);
        }
        return a / 2;
    }

    private static float[] regular(int n, float radius) {
        float[] xy = new float[2 * n];
        for (int i = 0; i < n; i++) {
            xy[2 * i] = (float) (radius * Math.cos(2 * Math.PI * i / n));
            xy[2 * i + 1] = (float) (radius * Math.sin(2 * Math.PI * i / n));
        }
        return xy;
    }

    @Test
    void nanCoordinateIsRefusedAsNotFinite() {
        InvalidShapeException e = refused(Rule.NOT_FINITE, 0f, 0f, 1f, 0f, Float.NaN, 1f);
        assertNamesVertex(e, 2, "(NaN, 1.0)");
    }

    @Test
    void infiniteCoordinateIsRefusedAsNotFinite() {
        InvalidShapeException e =
                refused(Rule.NOT_FINITE, 0f, 0f, 1f, Float.NEGATIVE_INFINITY, 1f, 1f);
        assertNamesVertex(e, 1, "(1.0, -Infinity)");
    }

    @Test
    void twoVerticesAreTooFew() {
        refused(Rule.TOO_FEW_VERTICES, 0f, 0f, 1f, 0f);
    }

    @Test
    void threeVerticesOfWhichTwoCoincideAreTooFew() {
        InvalidShapeException e = refused(Rule.TOO_FEW_VERTICES, 0f, 0f, 10f, 0f, 10f, 0.0001f);
        assertNamesVertex(e, 2, "(10.0, 1.0E-4)");
    }

    @Test
    void thirteenVerticesAreTooMany() {
        InvalidShapeException e = refused(Rule.TOO_MANY_VERTICES, regular(13, 10f));
        assertEquals(12, e.getVertexIndex(), e.getMessage());
        assertTrue(e.getMessage().contains("vertex 12 at ("), e.getMessage());
    }

    @Test
    void thirteenVerticesOfWhichOneIsCollinearAreAccepted() {
        float[] xy = new float[26];
        System.arraycopy(regular(12, 10f), 0, xy, 0, 24);
        // Midpoint of the closing edge from vertex 11 back to vertex 0.
        xy[24] = (xy[22] + xy[0]) / 2;
        xy[25] = (xy[23] + xy[1]) / 2;
        assertEquals(12, new Polygon(xy).getVertexCount());
    }

    @Test
    void collinearPointsAreDegenerate() {
        InvalidShapeException e = refused(Rule.DEGENERATE, 0f, 0f, 10f, 0f, 5f, 0f);
        assertTrue(e.getMessage().contains("one line"), e.getMessage());
        refused(Rule.DEGENERATE, 0f, 0f, 1f, 1f, 2f, 2f, 3f, 3.00001f);
    }

    @Test
    void dartIsNotConvex() {
        // An arrowhead: vertex 2 points back into the shape.
        InvalidShapeException e = refused(Rule.NOT_CONVEX, 0f, 0f, 10f, 5f, 4f, 5f, 10f, 10f);
        assertNamesVertex(e, 2, "(4.0, 5.0)");
    }

    @Test
    void bowTieIsNotConvex() {
        refused(Rule.NOT_CONVEX, 0f, 0f, 10f, 10f, 10f, 0f, 0f, 10f);
    }

    @Test
    void pentagramIsSelfIntersecting() {
        float[] pentagon = regular(5, 10f);
        float[] star = new float[10];
        for (int i = 0; i < 5; i++) {
            int k = (2 * i) % 5;
            star[2 * i] = pentagon[2 * k];
            star[2 * i + 1] = pentagon[2 * k + 1];
        }
        InvalidShapeException e = refused(Rule.SELF_INTERSECTING, star);
        assertTrue(e.getVertexIndex() >= 0 && e.getVertexIndex() < 5, e.getMessage());
        assertTrue(e.getMessage().contains("720 degrees"), e.getMessage());
    }

    @Test
    void outlineDoublingBackIsSelfIntersecting() {
        // Vertex 2 runs back along the edge from vertex 1 before the outline continues.
        InvalidShapeException e =
                refused(Rule.SELF_INTERSECTING, 0f, 0f, 10f, 0f, 5f, 0f, 5f, 5f);
        assertTrue(e.getMessage().contains("doubles back"), e.getMessage());
    }

    @Test
    void clockwiseInputIsStoredCounterClockwise() {
        Polygon cw = new Polygon(0f, 0f, 0f, 10f, 10f, 10f, 10f, 0f);
        Polygon ccw = new Polygon(0f, 0f, 10f, 0f, 10f, 10f, 0f, 10f);
        assertTrue(signedArea(cw) > 0);
        assertTrue(signedArea(ccw) > 0);
        assertEquals(100.0, signedArea(cw), 1e-4);
        for (Polygon p : new Polygon[] {cw, ccw}) {
            for (int i = 0; i < 4; i++) {
                int k = (i + 1) % 4;
                int m = (i + 2) % 4;
                double cross = (p.getVertexX(k) - p.getVertexX(i)) * (p.getVertexY(m) - p.getVertexY(k))
                        - (p.getVertexY(k) - p.getVertexY(i)) * (p.getVertexX(m) - p.getVertexX(k));
                assertTrue(cross > 0, "turn at vertex " + k);
            }
        }
    }

    @Test
    void normalsAreOutwardUnitVectorsOfEachEdge() {
        Polygon p = new Polygon(0f, 0f, 10f, 0f, 10f, 10f, 0f, 10f);
        assertEquals(0f, p.getNormalX(0), 1e-7);
        assertEquals(-1f, p.getNormalY(0), 1e-7);
        assertEquals(1f, p.getNormalX(1), 1e-7);
        assertEquals(0f, p.getNormalY(1), 1e-7);
        Polygon t = new Polygon(0f, 0f, 4f, 0f, 0f, 3f);
        // Hypotenuse from (4, 0) to (0, 3): outward normal (3, 4)/5.
        assertEquals(0.6f, t.getNormalX(1), 1e-6);
        assertEquals(0.8f, t.getNormalY(1), 1e-6);
    }

    @Test
    void collinearVertexIsRemoved() {
        Polygon p = new Polygon(0f, 0f, 5f, 0f, 10f, 0f, 10f, 10f, 0f, 10f);
        assertEquals(4, p.getVertexCount());
        for (int i = 0; i < 4; i++) {
            assertTrue(p.getVertexX(i) != 5f || p.getVertexY(i) != 0f);
        }
    }

    @Test
    void nearlyCollinearVertexWithinToleranceIsRemoved() {
        // 1e-5 off a 10 px edge is below 1e-4 × size.
        Polygon p = new Polygon(0f, 0f, 5f, -0.00001f, 10f, 0f, 10f, 10f, 0f, 10f);
        assertEquals(4, p.getVertexCount());
    }

    @Test
    void duplicateVertexIsMerged() {
        Polygon p = new Polygon(0f, 0f, 10f, 0f, 10f, 0f, 10f, 10f, 10.0004f, 10f, 0f, 10f, 0f, 0f);
        assertEquals(4, p.getVertexCount());
        assertEquals(100f, p.getArea(), 1e-4f);
    }

    @Test
    void oddCoordinateCountAndNullAreRefusedAsBadArguments() {
        IllegalArgumentException odd =
                assertThrows(IllegalArgumentException.class, () -> new Polygon(0f, 0f, 1f));
        assertTrue(odd.getMessage().contains("odd"), odd.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Polygon((float[]) null));
    }

    @Test
    void toleranceScalesWithPolygonSize() {
        // The same shapes scaled up by 1e4 clean the same way (scaled down they are too small).
        Polygon p = new Polygon(0f, 0f, 5e4f, 0f, 1e5f, 0f, 1e5f, 1e5f, 0f, 1e5f);
        assertEquals(4, p.getVertexCount());
        refused(Rule.NOT_CONVEX, 0f, 0f, 1e5f, 5e4f, 4e4f, 5e4f, 1e5f, 1e5f);
    }
}
