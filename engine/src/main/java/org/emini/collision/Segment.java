package org.emini.collision;

/**
 * A landscape line segment as the narrowphase sees it: two end points, a facing, and the far end
 * of the neighbouring segment at each end, if there is exactly one. A reusable flat struct, like
 * {@link Manifold}: fill it in place, nothing is allocated per use.
 *
 * <p>Facing, as in the original engine (y points down the screen): {@link #FACE_LEFT} stops bodies
 * on the left-hand side of the direction start → end, where (end − start) × (p − start) &lt; 0 with
 * a × b = a.x·b.y − a.y·b.x; {@link #FACE_RIGHT} stops bodies on the other side; {@link #FACE_NONE}
 * stops bodies on whichever side their centre is. A faced segment lets a body whose centre is on
 * the open side pass.
 *
 * <p>Neighbours make a chain of segments smooth: where the chain continues flat or bends towards
 * the body, the joint is not a corner, so no contact normal may point sideways out of it (a box
 * sliding along a floor made of many segments would otherwise catch on every joint).
 */
public final class Segment {
    /** Solid from both sides. */
    public static final int FACE_NONE = 0;
    /** Stops bodies on the left of start → end (a y-down screen), lets bodies on the right pass. */
    public static final int FACE_LEFT = 1;
    /** Stops bodies on the right of start → end (a y-down screen), lets bodies on the left pass. */
    public static final int FACE_RIGHT = 2;

    /** World x of the start point (px). */
    public float x1;
    /** World y of the start point (px). */
    public float y1;
    /** World x of the end point (px). */
    public float x2;
    /** World y of the end point (px). */
    public float y2;
    /** {@link #FACE_NONE}, {@link #FACE_LEFT} or {@link #FACE_RIGHT}. */
    public int face;
    /** Whether one other segment ends at the start point; its far end is (prevX, prevY). */
    public boolean hasPrev;
    /** World x of the far end of the segment joined at the start point (px). */
    public float prevX;
    /** World y of the far end of the segment joined at the start point (px). */
    public float prevY;
    /** Whether one other segment ends at the end point; its far end is (nextX, nextY). */
    public boolean hasNext;
    /** World x of the far end of the segment joined at the end point (px). */
    public float nextX;
    /** World y of the far end of the segment joined at the end point (px). */
    public float nextY;
    /**
     * The side to collide from: 0 to decide by the shape's centroid (and, for a faced segment, to
     * ignore a shape on the open side), or the side a contact with the same shape was found on
     * last time ({@link Collider#getSegmentSide()}: +1 the left of start → end on a y-down screen,
     * where a facing-2 segment blocks; −1 the other side), to keep it whatever the centroid, so a
     * shape pushed deeper than its centroid into a thin landscape is pushed back out rather than
     * through. A side that a faced segment does not block is ignored.
     */
    public int side;

    /** Creates a segment from (0, 0) to (0, 0), solid from both sides, with no neighbours. */
    public Segment() {
    }

    /**
     * Sets the end points and facing and forgets the neighbours.
     *
     * @param x1 start x (px)
     * @param y1 start y (px)
     * @param x2 end x (px)
     * @param y2 end y (px)
     * @param face the facing
     * @return this segment
     */
    public Segment set(float x1, float y1, float x2, float y2, int face) {
        this.x1 = x1;
        this.y1 = y1;
        this.x2 = x2;
        this.y2 = y2;
        this.face = face;
        hasPrev = false;
        hasNext = false;
        side = 0;
        return this;
    }

    @Override
    public String toString() {
        return "Segment[(" + x1 + ", " + y1 + ") to (" + x2 + ", " + y2 + "), face " + face + "]";
    }
}
