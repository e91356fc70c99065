package org.emini.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/** Segment–polygon and segment–circle contacts: sides, facing, joints, ids. */
class SegmentColliderTest {
    private static final float EPS = 1e-4f;

    private final Collider collider = new Collider();
    private final Manifold m = new Manifold();
    private final Segment floor = new Segment().set(-100f, 0f, 100f, 0f, Segment.FACE_NONE);
    private final Polygon box = Shape.createRectangle(20f, 20f);
    private final Circle ball = Shape.createCircle(10f);

    private void collide(Segment s, Shape shape, float x, float y, float angle, float speculative) {
        float c = (float) Math.cos(angle);
        float sn = (float) Math.sin(angle);
        // The shape is the whole body here: its centroid decides the side.
        float cx = x + c * shape.getCentroidX() - sn * shape.getCentroidY();
        float cy = y + sn * shape.getCentroidX() + c * shape.getCentroidY();
        collider.collideSegment(s, shape, x, y, c, sn, cx, cy, speculative, m);
    }

    @Test
    void boxOnASegmentGivesTwoPointsWithTheNormalFromTheSegmentToTheBox() {
        collide(floor, box, 5f, -9.5f, 0f, 0.5f);
        assertEquals(2, m.pointCount, m.toString());
        assertEquals(0f, m.normalX, EPS);
        assertEquals(-1f, m.normalY, EPS);
        for (int k = 0; k < 2; k++) {
            assertEquals(-0.5f, m.separation[k], EPS);
            assertEquals(0.25f, m.pointY[k], EPS);
        }
        assertEquals(-5f, Math.min(m.pointX[0], m.pointX[1]), EPS);
        assertEquals(15f, Math.max(m.pointX[0], m.pointX[1]), EPS);
        assertNotEquals(m.id[0], m.id[1]);
    }

    @Test
    void anUnfacedSegmentCollidesFromTheSideTheCentroidIsOn() {
        collide(floor, box, 0f, 9.5f, 0f, 0.5f);
        assertEquals(2, m.pointCount);
        assertEquals(1f, m.normalY, EPS);
        collide(floor, ball, 0f, 9.5f, 0f, 0.5f);
        assertEquals(1, m.pointCount);
        assertEquals(1f, m.normalY, EPS);
        assertEquals(-0.5f, m.separation[0], EPS);
    }

    /** Face 1 blocks the left of start → end on a y-down screen: above a left-to-right segment. */
    @Test
    void aFacedSegmentIgnoresShapesWhoseCentroidIsOnItsOpenSide() {
        Segment left = new Segment().set(-100f, 0f, 100f, 0f, Segment.FACE_LEFT);
        Segment right = new Segment().set(-100f, 0f, 100f, 0f, Segment.FACE_RIGHT);
        for (Shape s : new Shape[] {box, ball}) {
            collide(left, s, 0f, -9f, 0f, 0.5f);
            assertTrue(m.pointCount > 0, "face 1 stops a shape above");
            assertEquals(-1f, m.normalY, EPS);
            collide(left, s, 0f, 9f, 0f, 0.5f);
            assertEquals(0, m.pointCount, "face 1 lets a shape below pass");
            collide(right, s, 0f, 9f, 0f, 0.5f);
            assertTrue(m.pointCount > 0, "face 2 stops a shape below");
            assertEquals(1f, m.normalY, EPS);
            collide(right, s, 0f, -9f, 0f, 0.5f);
            assertEquals(0, m.pointCount, "face 2 lets a shape above pass");
        }
    }

    @Test
    void idsStayEqualWhileABoxSlidesAlongASegment() {
        collide(floor, box, 0f, -9.9f, 0f, 0.5f);
        int[] before = {m.id[0], m.id[1]};
        collide(floor, box, 30f, -9.8f, 0f, 0.5f);
        assertEquals(2, m.pointCount);
        assertEquals(before[0], m.id[0]);
        assertEquals(before[1], m.id[1]);
    }

    @Test
    void gapsUpToTheSpeculativeDistanceAreReported() {
        collide(floor, box, 0f, -12f, 0f, 3f);
        assertEquals(2, m.pointCount);
        assertEquals(2f, m.separation[0], EPS);
        collide(floor, box, 0f, -12f, 0f, 1f);
        assertEquals(0, m.pointCount);
        collide(floor, ball, 0f, -12f, 0f, 3f);
        assertEquals(2f, m.separation[0], EPS);
    }

    @Test
    void circleBeyondAFreeEndTouchesTheEndPointAlongTheLineOfCentres() {
        // Centre 6 px right of and 6 px above the end (100, 0): distance 8.49 < r = 10.
        collide(floor, ball, 106f, -6f, 0f, 0.5f);
        assertEquals(1, m.pointCount);
        float d = (float) Math.sqrt(72);
        assertEquals(6f / d, m.normalX, EPS);
        assertEquals(-6f / d, m.normalY, EPS);
        assertEquals(d - 10f, m.separation[0], EPS);
    }

    @Test
    void boxOverTheEndOfAFreeSegmentTipsOnTheCorner() {
        // Box turned by 0.3 rad whose lowest corner, 0.49 px above the segment, is left of the end.
        collide(floor, box, 92f, -13f, 0.3f, 0.5f);
        assertEquals(1, m.pointCount, m.toString());
        assertEquals(-1f, m.normalY, EPS);
        float lowest = -13f + 10f * (float) (Math.cos(0.3) + Math.sin(0.3));
        assertEquals(-lowest, m.separation[0], EPS);
        // Box entirely beyond the end, touching the end point with its left face.
        collide(floor, box, 109.8f, 5f, 0f, 0.5f);
        assertEquals(1, m.pointCount, m.toString());
        assertEquals(1f, m.normalX, EPS);
        assertEquals(-0.2f, m.separation[0], EPS);
    }

    /** Two collinear segments joined at x = 0. */
    private static Segment[] flatChain() {
        Segment a = new Segment().set(-100f, 0f, 0f, 0f, Segment.FACE_NONE);
        a.hasNext = true;
        a.nextX = 100f;
        a.nextY = 0f;
        Segment b = new Segment().set(0f, 0f, 100f, 0f, Segment.FACE_NONE);
        b.hasPrev = true;
        b.prevX = -100f;
        b.prevY = 0f;
        return new Segment[] {a, b};
    }

    /**
     * A box sunk 0.05 px into a flat chain and about to cross the joint never gets a sideways
     * normal from the next segment's end (the internal-edge problem); its free end would give one.
     */
    @Test
    void aFlatJointGivesNoSidewaysNormal() {
        Segment[] chain = flatChain();
        for (float x = -12f; x <= 12f; x += 0.25f) {
            for (Segment s : chain) {
                collide(s, box, x, -9.95f, 0f, 2f);
                if (m.pointCount > 0) {
                    assertEquals(0f, m.normalX, EPS, "x " + x + " " + m);
                    assertEquals(-1f, m.normalY, EPS);
                }
            }
        }
        // Without the join, the second segment's free end catches the box from the side.
        Segment lone = new Segment().set(0f, 0f, 100f, 0f, Segment.FACE_NONE);
        collide(lone, box, -10.5f, -9.95f, 0f, 2f);
        assertEquals(1, m.pointCount);
        assertEquals(-1f, m.normalX, EPS);
    }

    @Test
    void aCircleBeyondAFlatJointIsLeftToTheNeighbour() {
        Segment[] chain = flatChain();
        collide(chain[0], ball, 3f, -9.9f, 0f, 0.5f);
        assertEquals(0, m.pointCount);
        collide(chain[1], ball, 3f, -9.9f, 0f, 0.5f);
        assertEquals(1, m.pointCount);
        assertEquals(-1f, m.normalY, EPS);
    }

    /** A peak: up from (−100, 0) to (0, −50), down to (100, 0). Its top is a real corner. */
    @Test
    void aConvexJointIsACornerWithNormalsBetweenTheFaces() {
        Segment up = new Segment().set(-100f, 0f, 0f, -50f, Segment.FACE_NONE);
        up.hasNext = true;
        up.nextX = 100f;
        up.nextY = 0f;
        // A ball right above the peak: vertex region of both faces, normal straight up.
        collide(up, ball, 0f, -59f, 0f, 0.5f);
        assertEquals(1, m.pointCount);
        assertEquals(0f, m.normalX, EPS);
        assertEquals(-1f, m.normalY, EPS);
        assertEquals(-1f, m.separation[0], EPS);
        // A level box balanced on the peak: the box's bottom face is the reference.
        collide(up, box, 0f, -59.5f, 0f, 0.5f);
        assertEquals(1, m.pointCount, m.toString());
        assertEquals(-1f, m.normalY, EPS);
        assertEquals(-0.5f, m.separation[0], EPS);
    }

    @Test
    void zeroLengthSegmentsTouchNothingAndMultiShapesArePassedPartByPart() {
        Segment point = new Segment().set(5f, 5f, 5f, 5f, Segment.FACE_NONE);
        collide(point, ball, 5f, 5f, 0f, 1f);
        assertEquals(0, m.pointCount);
        MultiShape multi = Shape.createMultiShape(box);
        assertThrows(IllegalArgumentException.class, () -> collide(floor, multi, 0f, 0f, 0f, 1f));
    }

    /** A shape that touched from above keeps that side even once its centroid is below. */
    @Test
    void aKeptSideHoldsAShapeWhoseCentroidHasCrossed() {
        Segment s = new Segment().set(-100f, 0f, 100f, 0f, Segment.FACE_NONE);
        collide(s, box, 0f, 1f, 0f, 1f);
        assertEquals(1f, m.normalY, EPS, "by its centroid it is below: pushed down");
        assertEquals(1, collider.getSegmentSide());
        s.side = -1;
        collide(s, box, 0f, 1f, 0f, 1f);
        assertEquals(2, m.pointCount);
        assertEquals(-1f, m.normalY, EPS, "kept above: pushed back up");
        assertEquals(-11f, m.separation[0], EPS);
        assertEquals(-1, collider.getSegmentSide());
        // A faced segment keeps only the side it blocks.
        Segment left = new Segment().set(-100f, 0f, 100f, 0f, Segment.FACE_LEFT);
        left.side = 1;
        collide(left, box, 0f, 1f, 0f, 1f);
        assertEquals(0, m.pointCount);
        assertEquals(0, collider.getSegmentSide());
    }

    /**
     * A peak from (−100, 10) up to (0, 0) and down to (100, 10): a box above the top, level or
     * tilted less than the faces, touches the top joint only, with its own face as the normal.
     */
    @Test
    void boxAboveAPeakTouchesTheTopJointAlongItsOwnFace() {
        Segment up = new Segment().set(-100f, 10f, 0f, 0f, Segment.FACE_NONE);
        up.hasNext = true;
        up.nextX = 100f;
        up.nextY = 10f;
        for (float angle : new float[] {0f, 0.05f, -0.05f}) {
            collide(up, box, 0f, -10.5f, angle, 1f);
            assertEquals(1, m.pointCount, m.toString());
            assertEquals((float) Math.sin(angle), m.normalX, EPS, "angle " + angle);
            assertEquals(-(float) Math.cos(angle), m.normalY, EPS);
            assertEquals(10.5f * (float) Math.cos(angle) - 10f, m.separation[0], 1e-3f);
        }
    }
}
