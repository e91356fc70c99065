package org.emini.shape;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Factories' vertex layout and bounding boxes. */
class ShapeGeometryTest {
    @Test
    void rectangleIsCentredOnTheOrigin() {
        Polygon r = Shape.createRectangle(6f, 4f);
        assertEquals(4, r.getVertexCount());
        assertEquals(0f, r.getCentroidX(), 1e-6);
        assertEquals(0f, r.getCentroidY(), 1e-6);
        float[] box = new float[4];
        r.computeAabb(0f, 0f, 1f, 0f, box);
        assertEquals(-3f, box[0]);
        assertEquals(-2f, box[1]);
        assertEquals(3f, box[2]);
        assertEquals(2f, box[3]);
    }

    @Test
    void regularPolygonHasVertexZeroAtAngleZero() {
        Polygon p = Shape.createRegularPolygon(7f, 6);
        assertEquals(6, p.getVertexCount());
        assertEquals(7f, p.getVertexX(0), 1e-6);
        assertEquals(0f, p.getVertexY(0), 1e-6);
        assertEquals(3.5f, p.getVertexX(1), 1e-5);
        assertEquals(7f * Math.sqrt(3) / 2, p.getVertexY(1), 1e-5);
        assertEquals(7f, p.getBoundingRadius(), 1e-5);
    }

    @Test
    void rotatedRectangleBoxCoversItsCorners() {
        Polygon r = Shape.createRectangle(20f, 10f);
        float c = (float) Math.cos(Math.PI / 2);
        float s = (float) Math.sin(Math.PI / 2);
        float[] box = new float[4];
        r.computeAabb(100f, 50f, c, s, box);
        assertEquals(95f, box[0], 1e-4);
        assertEquals(40f, box[1], 1e-4);
        assertEquals(105f, box[2], 1e-4);
        assertEquals(60f, box[3], 1e-4);
    }

    @Test
    void rotationMapsLocalPointsCounterClockwiseInMathOrientation() {
        // Local (10, 0) rotated by +90° goes to (0, 10): the box of a thin bar along x becomes tall.
        Polygon bar = Shape.createPolygon(0f, -1f, 10f, -1f, 10f, 1f, 0f, 1f);
        float[] box = new float[4];
        bar.computeAabb(0f, 0f, 0f, 1f, box);
        assertEquals(-1f, box[0], 1e-6);
        assertEquals(0f, box[1], 1e-6);
        assertEquals(1f, box[2], 1e-6);
        assertEquals(10f, box[3], 1e-6);
    }

    @Test
    void offsetCircleBoxFollowsTheRotatedCentre() {
        Circle c = new Circle(2f, 10f, 0f);
        float[] box = new float[4];
        c.computeAabb(5f, 5f, 0f, 1f, box);
        assertEquals(3f, box[0], 1e-6);
        assertEquals(13f, box[1], 1e-6);
        assertEquals(7f, box[2], 1e-6);
        assertEquals(17f, box[3], 1e-6);
    }
}
