package org.emini.collision;

import org.emini.math.EMath;
import org.emini.shape.Circle;
import org.emini.shape.Polygon;

/**
 * Segment–circle and segment–polygon narrowphase for the landscape: one-sided where the segment is
 * faced, and smooth across the joints of a chain of segments.
 *
 * <p>The side a shape collides from is decided by its centroid: a faced segment ignores a shape
 * whose centroid is on its open side, so a body coming from there passes through and is never
 * pushed through to the blocking side; an unfaced segment collides from whichever side the
 * centroid is on. A shape whose centroid lies beyond an end where the chain continues flat or
 * bends towards it is left to the neighbouring segment. The contact normal is then confined to the cone of directions the segment owns:
 * its face normal, and around an end either the quarter turn to the outward tangent (a free end),
 * the turn to the neighbour's face normal (a convex joint), or nothing (a flat or concave joint,
 * which the neighbour covers).
 */
final class SegmentCollider {
    // Below this fraction of the longer of the two, a segment is a point and collides with nothing.
    private static final float MIN_LENGTH = 1e-6f;
    // Sine of the angle by which a joint must bend to count as convex, and the angular tolerance
    // at the edges of a normal cone (so a box lying on the neighbour still matches it).
    private static final float ANGLE_TOLERANCE = 1e-4f;

    private final PolygonCollider polygons;

    // The segment being collided: unit direction, face normal (towards the shape), and the far
    // edge of the normal cone at each end; coneStart/coneEnd false where the end owns no cone.
    private float ux;
    private float uy;
    private float nx;
    private float ny;
    private boolean coneStart;
    private float startEdgeX;
    private float startEdgeY;
    private boolean coneEnd;
    private float endEdgeX;
    private float endEdgeY;

    SegmentCollider(PolygonCollider polygons) {
        this.polygons = polygons;
    }

    /**
     * Sets up the segment against a shape whose centroid is at (cx, cy); returns false when the
     * shape cannot collide with it (a point segment, or the centroid on the open side).
     */
    private boolean begin(Segment seg, float cx, float cy) {
        float dx = seg.x2 - seg.x1;
        float dy = seg.y2 - seg.y1;
        float length = EMath.sqrt(dx * dx + dy * dy);
        float size = Math.max(Math.max(Math.abs(seg.x1), Math.abs(seg.y1)),
                Math.max(Math.abs(seg.x2), Math.abs(seg.y2)));
        if (!(length > MIN_LENGTH * Math.max(size, 1f))) {
            return false;
        }
        ux = dx / length;
        uy = dy / length;
        // The left normal (−uy, ux): a body at p is on the face-1 side when (p − start)·left < 0.
        float side = (cx - seg.x1) * -uy + (cy - seg.y1) * ux;
        float sign;
        if (seg.face == Segment.FACE_LEFT) {
            sign = -1f;
        } else if (seg.face == Segment.FACE_RIGHT) {
            sign = 1f;
        } else {
            sign = side >= 0f ? 1f : -1f;
        }
        if (side * sign < 0f) {
            return false;
        }
        nx = -sign * uy;
        ny = sign * ux;
        coneStart = seg.hasPrev ? jointCone(seg.x1 - seg.prevX, seg.y1 - seg.prevY, dx, dy, sign, true)
                : freeCone(-ux, -uy, true);
        coneEnd = seg.hasNext ? jointCone(dx, dy, seg.nextX - seg.x2, seg.nextY - seg.y2, sign, false)
                : freeCone(ux, uy, false);
        // Beyond a flat or concave joint the shape is over the neighbour, which covers it: a box
        // on a cliff top is not caught by the cliff's face just because its corner dips into the
        // slop below the top.
        float t = (cx - seg.x1) * ux + (cy - seg.y1) * uy;
        return !(t < 0f && seg.hasPrev && !coneStart) && !(t > length && seg.hasNext && !coneEnd);
    }

    private boolean freeCone(float tx, float ty, boolean start) {
        setEdge(tx, ty, start);
        return true;
    }

    /**
     * The cone at a joint where the chain runs along (inX, inY) into the joint and (outX, outY) out
     * of it: the joint is a corner only if the chain bends away from the side the normal is on.
     */
    private boolean jointCone(float inX, float inY, float outX, float outY, float sign,
            boolean start) {
        float inLength = EMath.sqrt(inX * inX + inY * inY);
        float outLength = EMath.sqrt(outX * outX + outY * outY);
        if (!(inLength > 0f) || !(outLength > 0f)) {
            // A point neighbour: treat the end as free.
            return freeCone(start ? -ux : ux, start ? -uy : uy, start);
        }
        float turn = (inX * outY - inY * outX) / (inLength * outLength);
        if (turn * sign > -ANGLE_TOLERANCE) {
            return false;
        }
        // The neighbour's face normal on the same side of the chain.
        float ox = start ? inX / inLength : outX / outLength;
        float oy = start ? inY / inLength : outY / outLength;
        setEdge(-sign * oy, sign * ox, start);
        return true;
    }

    private void setEdge(float ex, float ey, boolean start) {
        if (start) {
            startEdgeX = ex;
            startEdgeY = ey;
        } else {
            endEdgeX = ex;
            endEdgeY = ey;
        }
    }

    /** Whether a contact normal (from the segment to the shape) lies in the segment's cone. */
    private boolean admissible(float mx, float my) {
        if (mx * nx + my * ny >= 1f - ANGLE_TOLERANCE * ANGLE_TOLERANCE) {
            return true;
        }
        boolean atStart = mx * ux + my * uy < 0f;
        if (atStart ? !coneStart : !coneEnd) {
            return false;
        }
        float ex = atStart ? startEdgeX : endEdgeX;
        float ey = atStart ? startEdgeY : endEdgeY;
        // Inside the arc from the face normal to the cone's edge (less than a half turn).
        float k = nx * ey - ny * ex;
        float k1 = (nx * my - ny * mx) * k;
        float k2 = (mx * ey - my * ex) * k;
        return k1 >= -ANGLE_TOLERANCE * Math.abs(k) && k2 >= -ANGLE_TOLERANCE * Math.abs(k);
    }

    void collideCircle(Segment seg, Circle b, float bx, float by, float bc, float bs,
            float speculativeDistance, Manifold out) {
        out.pointCount = 0;
        float px = bx + bc * b.getCenterX() - bs * b.getCenterY();
        float py = by + bs * b.getCenterX() + bc * b.getCenterY();
        if (!begin(seg, px, py)) {
            return;
        }
        float radius = b.getRadius();
        float dx = seg.x2 - seg.x1;
        float dy = seg.y2 - seg.y1;
        float t = (px - seg.x1) * ux + (py - seg.y1) * uy;
        float length = dx * ux + dy * uy;
        if (t >= 0f && t <= length) {
            float distance = (px - seg.x1) * nx + (py - seg.y1) * ny;
            float separation = distance - radius;
            if (separation > speculativeDistance) {
                return;
            }
            float h = 0.5f * (distance + radius);
            writeOnePoint(nx, ny, px - h * nx, py - h * ny, separation, out);
            return;
        }
        float vx = t < 0f ? seg.x1 : seg.x2;
        float vy = t < 0f ? seg.y1 : seg.y2;
        float ex = px - vx;
        float ey = py - vy;
        float distance = EMath.sqrt(ex * ex + ey * ey);
        float separation = distance - radius;
        if (separation > speculativeDistance) {
            return;
        }
        float mx = nx;
        float my = ny;
        if (distance > 0f) {
            mx = ex / distance;
            my = ey / distance;
        }
        if (!admissible(mx, my)) {
            return;
        }
        float h = 0.5f * separation;
        writeOnePoint(mx, my, vx + h * mx, vy + h * my, separation, out);
    }

    void collidePolygon(Segment seg, Polygon b, float bx, float by, float bc, float bs,
            float speculativeDistance, Manifold out) {
        out.pointCount = 0;
        float lx = b.getCentroidX();
        float ly = b.getCentroidY();
        if (!begin(seg, bx + bc * lx - bs * ly, by + bs * lx + bc * ly)) {
            return;
        }
        int faces = 0;
        for (int i = 0; i < b.getVertexCount(); i++) {
            // The normal this face would give, from the segment to the polygon: minus its own.
            float mx = bc * b.getNormalX(i) - bs * b.getNormalY(i);
            float my = bs * b.getNormalX(i) + bc * b.getNormalY(i);
            if (admissible(-mx, -my)) {
                faces |= 1 << i;
            }
        }
        // The collider's first face must have the outward normal n: order the ends accordingly.
        boolean forward = nx * uy - ny * ux > 0f;
        float sx1 = forward ? seg.x1 : seg.x2;
        float sy1 = forward ? seg.y1 : seg.y2;
        float sx2 = forward ? seg.x2 : seg.x1;
        float sy2 = forward ? seg.y2 : seg.y1;
        polygons.collideSegment(sx1, sy1, sx2, sy2, nx, ny, b, bx, by, bc, bs, faces,
                speculativeDistance, out);
    }

    private static void writeOnePoint(float nx, float ny, float px, float py, float separation,
            Manifold out) {
        out.normalX = nx;
        out.normalY = ny;
        out.pointX[0] = px;
        out.pointY[0] = py;
        out.separation[0] = separation;
        out.id[0] = 0;
        out.pointCount = 1;
    }
}
