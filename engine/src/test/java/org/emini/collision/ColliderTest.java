package org.emini.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.emini.shape.Circle;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/** Specific contact configurations with known answers. */
class ColliderTest {
    private static final float EPS = 1e-4f;
    private static final float COS45 = (float) Math.cos(Math.PI / 4);

    private final Collider collider = new Collider();
    private final Manifold m = new Manifold();
    private final Polygon ground = Shape.createRectangle(100f, 20f);
    private final Polygon box = Shape.createRectangle(20f, 20f);

    /** Ground centred on the origin (top face at y = −10), the other shape unrotated. */
    private void onGround(Shape other, float x, float y, float speculative) {
        collider.collide(ground, 0f, 0f, 1f, 0f, other, x, y, 1f, 0f, speculative, m);
    }

    @Test
    void boxRestingFaceToFaceGivesTwoPointsWithTheOverlapAsSeparation() {
        onGround(box, 0f, -19.5f, 1f);
        assertEquals(2, m.pointCount, m.toString());
        assertEquals(0f, m.normalX, EPS);
        assertEquals(-1f, m.normalY, EPS);
        float[] xs = {m.pointX[0], m.pointX[1]};
        java.util.Arrays.sort(xs);
        assertEquals(-10f, xs[0], EPS);
        assertEquals(10f, xs[1], EPS);
        for (int k = 0; k < 2; k++) {
            assertEquals(-0.5f, m.separation[k], EPS);
            assertEquals(-9.75f, m.pointY[k], EPS);
        }
        assertNotEquals(m.id[0], m.id[1]);
    }

    @Test
    void boxCornerOnFaceGivesOnePointAtTheCorner() {
        float y = -10f - 10f * (float) Math.sqrt(2) + 0.3f;
        collider.collide(ground, 0f, 0f, 1f, 0f, box, 0f, y, COS45, COS45, 1f, m);
        assertEquals(1, m.pointCount, m.toString());
        assertEquals(-0.3f, m.separation[0], 1e-3);
        assertEquals(0f, m.pointX[0], 1e-3);
        assertEquals(-9.85f, m.pointY[0], 1e-3);
        assertEquals(-1f, m.normalY, EPS);
    }

    @Test
    void idsStayEqualWhileABoxSlides() {
        onGround(box, 0f, -19.9f, 1f);
        int[] before = {m.id[0], m.id[1]};
        onGround(box, 3f, -19.8f, 1f);
        assertEquals(2, m.pointCount);
        assertEquals(before[0], m.id[0]);
        assertEquals(before[1], m.id[1]);
    }

    @Test
    void idsSurviveAChangeOfReferenceFace() {
        // Equal boxes: A supplies the reference face; swapped, the other box does.
        collider.collide(box, 0f, 0f, 1f, 0f, box, 2f, -19.5f, 1f, 0f, 1f, m);
        int[] ab = {m.id[0], m.id[1]};
        float[] abX = {m.pointX[0], m.pointX[1]};
        collider.collide(box, 2f, -19.5f, 1f, 0f, box, 0f, 0f, 1f, 0f, 1f, m);
        assertEquals(2, m.pointCount);
        // Same points; each key names (vertex of A, vertex of B), so swapping A and B swaps the
        // bytes of the key.
        for (int k = 0; k < 2; k++) {
            int j = Math.abs(m.pointX[k] - abX[0]) < EPS ? 0 : 1;
            int swapped = ((ab[j] & 0xff) << 8) | (ab[j] >> 8);
            assertEquals(swapped, m.id[k]);
        }
    }

    @Test
    void speculativePointsAreReportedOnlyWithinTheSpeculativeDistance() {
        onGround(box, 0f, -20.5f, 1f);
        assertEquals(2, m.pointCount);
        assertEquals(0.5f, m.separation[0], EPS);
        assertEquals(0.5f, m.separation[1], EPS);
        onGround(box, 0f, -20.5f, 0.25f);
        assertEquals(0, m.pointCount);
    }

    @Test
    void tiltedBoxReportsOnlyItsNearCornerWithinTheSpeculativeDistance() {
        float angle = 0.1f;
        float c = (float) Math.cos(angle);
        float s = (float) Math.sin(angle);
        // Lowest corner just touching: the other end of the bottom edge is ~2 px higher.
        float lowest = 10f * c + 10f * s;
        collider.collide(ground, 0f, 0f, 1f, 0f, box, 0f, -10f - lowest - 0.1f, c, s, 0.5f, m);
        assertEquals(1, m.pointCount, m.toString());
        assertEquals(0.1f, m.separation[0], 1e-3);
    }

    @Test
    void cornerToCornerGapIsMeasuredAlongTheDiagonal() {
        // Corners (10, 10) and (11, 11): the true gap is √2 although each face separates by 1.
        collider.collide(box, 0f, 0f, 1f, 0f, box, 21f, 21f, 1f, 0f, 2f, m);
        assertEquals(1, m.pointCount, m.toString());
        assertEquals(Math.sqrt(2), m.separation[0], EPS);
        assertEquals(COS45, m.normalX, EPS);
        assertEquals(COS45, m.normalY, EPS);
        assertEquals(10.5f, m.pointX[0], EPS);
        assertEquals(10.5f, m.pointY[0], EPS);
        collider.collide(box, 0f, 0f, 1f, 0f, box, 21f, 21f, 1f, 0f, 1.2f, m);
        assertEquals(0, m.pointCount);
    }

    @Test
    void rotatedReferenceFrameGivesWorldNormalAndPoints() {
        // A 20 × 100 bar turned by 90° lies like the ground.
        Polygon bar = Shape.createRectangle(20f, 100f);
        collider.collide(bar, 0f, 0f, 0f, 1f, box, 0f, -19.5f, 1f, 0f, 1f, m);
        assertEquals(2, m.pointCount);
        assertEquals(0f, m.normalX, EPS);
        assertEquals(-1f, m.normalY, EPS);
        assertEquals(-0.5f, m.separation[0], EPS);
        assertEquals(-9.75f, m.pointY[0], EPS);
    }

    @Test
    void swappedPolygonsFlipTheNormal() {
        collider.collide(box, 0f, -19.5f, 1f, 0f, ground, 0f, 0f, 1f, 0f, 1f, m);
        assertEquals(2, m.pointCount);
        assertEquals(1f, m.normalY, EPS);
        assertEquals(-0.5f, m.separation[0], EPS);
    }

    @Test
    void farFromTheOriginTheContactKeepsItsPrecision() {
        float x = 10000f;
        float y = 10000f;
        collider.collide(ground, x, y, 1f, 0f, box, x, y - 19.5f, 1f, 0f, 1f, m);
        assertEquals(2, m.pointCount);
        assertEquals(-0.5f, m.separation[0], 2e-3);
        assertEquals(-0.5f, m.separation[1], 2e-3);
    }

    @Test
    void circleOnAFaceUsesTheFaceNormal() {
        onGround(new Circle(5f), 3f, -14f, 1f);
        assertEquals(1, m.pointCount);
        assertEquals(0f, m.normalX, EPS);
        assertEquals(-1f, m.normalY, EPS);
        assertEquals(-1f, m.separation[0], EPS);
        assertEquals(3f, m.pointX[0], EPS);
        assertEquals(-9.5f, m.pointY[0], EPS);
        assertEquals(0, m.id[0]);
    }

    @Test
    void circleInAVertexRegionUsesTheDirectionFromTheVertex() {
        // Corner (10, 10); centre (13, 14) is 5 away; radius 6 overlaps by 1.
        collider.collide(box, 0f, 0f, 1f, 0f, new Circle(6f), 13f, 14f, 1f, 0f, 1f, m);
        assertEquals(1, m.pointCount);
        assertEquals(0.6f, m.normalX, EPS);
        assertEquals(0.8f, m.normalY, EPS);
        assertEquals(-1f, m.separation[0], EPS);
        assertEquals(9.7f, m.pointX[0], EPS);
        assertEquals(9.6f, m.pointY[0], EPS);
    }

    @Test
    void circleWithCentreInsideThePolygonIsPushedOutThroughTheNearestFace() {
        onGround(new Circle(5f), 0f, -8f, 1f);
        assertEquals(1, m.pointCount);
        assertEquals(-1f, m.normalY, EPS);
        assertEquals(-7f, m.separation[0], EPS);
    }

    @Test
    void circleFirstGivesTheOppositeNormalAndTheSamePoint() {
        Circle ball = new Circle(6f);
        collider.collide(box, 0f, 0f, 1f, 0f, ball, 13f, 14f, 1f, 0f, 1f, m);
        float nx = m.normalX;
        float px = m.pointX[0];
        collider.collide(ball, 13f, 14f, 1f, 0f, box, 0f, 0f, 1f, 0f, 1f, m);
        assertEquals(1, m.pointCount);
        assertEquals(-nx, m.normalX, EPS);
        assertEquals(px, m.pointX[0], EPS);
        assertEquals(-1f, m.separation[0], EPS);
    }

    @Test
    void offsetCircleOnARotatedBodyIsPlacedByTheRotation() {
        // Centre offset (10, 0) turned by 90° lands at (0, 10) from the body origin.
        Circle part = new Circle(5f, 10f, 0f);
        onGround(part, 0f, -24f, 1f);
        assertEquals(0, m.pointCount, "unrotated, the part hangs 9 px above the ground");
        collider.collide(ground, 0f, 0f, 1f, 0f, part, 0f, -24f, 0f, 1f, 1f, m);
        assertEquals(1, m.pointCount);
        assertEquals(-1f, m.separation[0], EPS);
        assertEquals(0f, m.pointX[0], EPS);
    }

    @Test
    void circlesTouchAlongTheLineOfCentres() {
        // Centres 5 apart, radii 3 and 4: overlap 2; surface points (1.8, 2.4) and (0.6, 0.8).
        collider.collide(new Circle(3f), 0f, 0f, 1f, 0f, new Circle(4f), 3f, 4f, 1f, 0f, 0f, m);
        assertEquals(1, m.pointCount);
        assertEquals(0.6f, m.normalX, EPS);
        assertEquals(0.8f, m.normalY, EPS);
        assertEquals(-2f, m.separation[0], EPS);
        assertEquals(1.2f, m.pointX[0], EPS);
        assertEquals(1.6f, m.pointY[0], EPS);
        // Centres 10 apart: gap 3, beyond a speculative distance of 0.4.
        collider.collide(new Circle(3f), 0f, 0f, 1f, 0f, new Circle(4f), 6f, 8f, 1f, 0f, 0.4f, m);
        assertEquals(0, m.pointCount);
    }

    @Test
    void coincidentCirclesGetTheFixedNormal() {
        collider.collide(new Circle(3f), 5f, 5f, 1f, 0f, new Circle(2f), 5f, 5f, 1f, 0f, 0f, m);
        assertEquals(1, m.pointCount);
        assertEquals(0f, m.normalX);
        assertEquals(1f, m.normalY);
        assertEquals(-5f, m.separation[0], EPS);
    }

    @Test
    void clearResetsEveryField() {
        onGround(box, 0f, -19.5f, 1f);
        m.clear();
        assertEquals(0, m.pointCount);
        assertEquals(0f, m.normalY);
        assertEquals(0f, m.separation[1]);
        assertEquals(0, m.id[0]);
    }

    @Test
    void collidingDoesNotAllocate() {
        com.sun.management.ThreadMXBean bean =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        Shape[] shapes = {ground, box, new Circle(5f), Shape.createRegularPolygon(8f, 7)};
        for (int warm = 0; warm < 20000; warm++) {
            collideAll(shapes, warm);
        }
        long id = Thread.currentThread().getId();
        long before = bean.getThreadAllocatedBytes(id);
        for (int i = 0; i < 20000; i++) {
            collideAll(shapes, i);
        }
        long allocated = bean.getThreadAllocatedBytes(id) - before;
        // A few hundred bytes of measurement noise are tolerated; one object per call is not.
        assertTrue(allocated < 4096, allocated + " bytes allocated");
    }

    private void collideAll(Shape[] shapes, int i) {
        float t = (i % 100) * 0.01f;
        for (Shape a : shapes) {
            for (Shape b : shapes) {
                collider.collide(a, 0f, 0f, 1f, 0f, b, 5f + t, -18f, 0.96f, 0.28f, 1f, m);
            }
        }
    }
}
