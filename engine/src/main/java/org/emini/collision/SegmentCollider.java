package org.emini.collision;

import org.emini.math.EMath;
import org.emini.shape.Circle;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * Segment–circle and segment–polygon narrowphase for the landscape: one-sided where the segment is
 * faced, and smooth across the joints of a chain of segments.
 *
 * <p>The side a shape collides from is decided by one point of its body (a multi-shape body passes
 * or is stopped as a whole): for a faced segment its position (the local origin), as in the original
 * engine, whose one-way platforms let a body through by where its origin is; for an unfaced segment
 * its centre of mass, because an off-centre shape's origin may cross the line before the shape
 * touches it, and the segment then pushed the shape through to the other side. A faced
 * segment ignores a body on its open side, so a body coming from there passes through and is never
 * pushed through to the blocking side, while a body exactly on the line is blocked; an unfaced
 * segment collides from whichever side the body is on. Once a shape touches, the caller may keep
 * its side ({@link Segment#side}), so a body pushed past the line is pushed back rather than
 * through. A shape whose centroid lies beyond an end where the chain continues flat or bends towards it, and behind the
 * neighbour's face, is on the neighbour's other side and is ignored. The contact normal is then confined to the cone of directions the segment owns:
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

    // Gaps from the clipping that fall this much short of the closest distance are not trusted (px).
    private static final float CLOSE_TOLERANCE = 1e-3f;

    private final PolygonCollider polygons;
    /** The side the last call collided from, 0 if the segment ignored the shape. */
    int foundSide;
    private final float[] px = new float[Shape.MAX_VERTICES];
    private final float[] py = new float[Shape.MAX_VERTICES];

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

    /** The point that decides the side: the body's origin for a faced segment, its centre of mass otherwise. */
    private static float sidePointX(Segment seg, float originX, float centreX) {
        return seg.face == Segment.FACE_NONE ? centreX : originX;
    }

    private static float sidePointY(Segment seg, float originY, float centreY) {
        return seg.face == Segment.FACE_NONE ? centreY : originY;
    }

    /**
     * Sets up the segment against a shape whose body's side point is at (ox, oy), and whose own
     * centroid is at (cx, cy); returns false when the shape cannot collide with it
     * (a point segment, the body on the open side, or the shape on a neighbour's other side).
     */
    private boolean begin(Segment seg, float ox, float oy, float cx, float cy) {
        int kept = seg.side;
        foundSide = 0;
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
        // A body on the line is blocked.
        float side = (ox - seg.x1) * -uy + (oy - seg.y1) * ux;
        int blocking = seg.face == Segment.FACE_LEFT ? -1 : (seg.face == Segment.FACE_RIGHT ? 1 : 0);
        int sign;
        if (kept != 0 && (blocking == 0 || kept == blocking)) {
            // The side of the last contact is kept, so a deep overlap is undone, not completed.
            sign = kept;
        } else {
            sign = blocking != 0 ? blocking : (side >= 0f ? 1 : -1);
            if (side * sign < 0f) {
                return false;
            }
        }
        nx = -sign * uy;
        ny = sign * ux;
        coneStart = seg.hasPrev ? jointCone(seg.x1 - seg.prevX, seg.y1 - seg.prevY, dx, dy, sign, true)
                : freeCone(-ux, -uy, true);
        coneEnd = seg.hasNext ? jointCone(dx, dy, seg.nextX - seg.x2, seg.nextY - seg.y2, sign, false)
                : freeCone(ux, uy, false);
        // Beyond a flat or concave joint and behind the neighbour's face, the shape is on the
        // neighbour's other side: a box on a cliff top is not caught by the inner face of the cliff
        // just because its corner dips into the slop below the top.
        float t = (cx - seg.x1) * ux + (cy - seg.y1) * uy;
        if (t < 0f && seg.hasPrev && !coneStart
                && (cx - seg.x1) * startEdgeX + (cy - seg.y1) * startEdgeY < 0f) {
            return false;
        }
        if (t > length && seg.hasNext && !coneEnd
                && (cx - seg.x2) * endEdgeX + (cy - seg.y2) * endEdgeY < 0f) {
            return false;
        }
        foundSide = sign;
        return true;
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
        // The neighbour's face normal on the same side of the chain: the cone's edge at a corner,
        // and what tells a shape in front of the neighbour from one behind it elsewhere.
        float ox = start ? inX / inLength : outX / outLength;
        float oy = start ? inY / inLength : outY / outLength;
        setEdge(-sign * oy, sign * ox, start);
        float turn = (inX * outY - inY * outX) / (inLength * outLength);
        return turn * sign <= -ANGLE_TOLERANCE;
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

    void collideCircle(Segment seg, Circle b, float bx, float by, float bc, float bs, float sideX, float sideY,
            float speculativeDistance, Manifold out) {
        out.pointCount = 0;
        float px = bx + bc * b.getCenterX() - bs * b.getCenterY();
        float py = by + bs * b.getCenterX() + bc * b.getCenterY();
        if (!begin(seg, sidePointX(seg, bx, sideX), sidePointY(seg, by, sideY), px, py)) {
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

    void collidePolygon(Segment seg, Polygon b, float bx, float by, float bc, float bs, float sideX, float sideY,
            float speculativeDistance, Manifold out) {
        out.pointCount = 0;
        float lx = b.getCentroidX();
        float ly = b.getCentroidY();
        if (!begin(seg, sidePointX(seg, bx, sideX), sidePointY(seg, by, sideY), bx + bc * lx - bs * ly,
                by + bs * lx + bc * ly)) {
            return;
        }
        // The polygon relative to the segment's start, in world orientation.
        int n = b.getVertexCount();
        float length = (seg.x2 - seg.x1) * ux + (seg.y2 - seg.y1) * uy;
        float ex = length * ux;
        float ey = length * uy;
        float low = Float.POSITIVE_INFINITY;
        float high = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            px[i] = bx + bc * b.getVertexX(i) - bs * b.getVertexY(i) - seg.x1;
            py[i] = by + bs * b.getVertexX(i) + bc * b.getVertexY(i) - seg.y1;
            float d = px[i] * nx + py[i] * ny;
            low = Math.min(low, d);
            high = Math.max(high, d);
        }
        // The full separating-axis test (both segment normals, every polygon face) tells whether
        // the two are apart; only then can the closest points be trusted over the cone's axes.
        float separation = Math.max(low, -high);
        int faces = 0;
        for (int i = 0; i < n; i++) {
            float mx = bc * b.getNormalX(i) - bs * b.getNormalY(i);
            float my = bs * b.getNormalX(i) + bc * b.getNormalY(i);
            separation = Math.max(separation, Math.min(-(px[i] * mx + py[i] * my),
                    (ex - px[i]) * mx + (ey - py[i]) * my));
            // The normal this face would give, from the segment to the polygon: minus its own.
            if (admissible(-mx, -my)) {
                faces |= 1 << i;
            }
        }
        if (separation > speculativeDistance) {
            return;
        }
        if (separation > 0f) {
            apart(seg, b, bx, by, bc, bs, n, length, speculativeDistance, out);
            return;
        }
        overlapping(seg, b, bx, by, bc, bs, faces, speculativeDistance, out);
    }

    /**
     * The polygon overlaps the segment: separating axes restricted to the cone, then clipping, with
     * the segment as a two-vertex polygon whose first face has the outward normal n.
     */
    private void overlapping(Segment seg, Polygon b, float bx, float by, float bc, float bs, int faces,
            float speculativeDistance, Manifold out) {
        boolean forward = nx * uy - ny * ux > 0f;
        float sx1 = forward ? seg.x1 : seg.x2;
        float sy1 = forward ? seg.y1 : seg.y2;
        float sx2 = forward ? seg.x2 : seg.x1;
        float sy2 = forward ? seg.y2 : seg.y1;
        polygons.collideSegment(sx1, sy1, sx2, sy2, nx, ny, b, bx, by, bc, bs, faces,
                speculativeDistance, out);
    }

    /**
     * The polygon is apart from the segment: find the closest points. If the segment's closest
     * point is inside it, the contact is on its face (clipped, one or two points); if it is an end,
     * the contact joins that end to the polygon when that normal lies in the end's cone, and is on
     * the face otherwise.
     */
    private void apart(Segment seg, Polygon b, float bx, float by, float bc, float bs, int n,
            float length, float speculativeDistance, Manifold out) {
        float best = Float.POSITIVE_INFINITY;
        boolean interior = false;
        int end = 0;
        int feature = 0;
        float qx = 0f;
        float qy = 0f;
        float sx = 0f;
        float sy = 0f;
        for (int i = 0; i < n; i++) {
            float t = px[i] * ux + py[i] * uy;
            t = t < 0f ? 0f : (t > length ? length : t);
            float dx = px[i] - t * ux;
            float dy = py[i] - t * uy;
            float d2 = dx * dx + dy * dy;
            if (d2 < best) {
                best = d2;
                interior = t > 0f && t < length;
                end = t > 0f ? 1 : 0;
                feature = i;
                qx = px[i];
                qy = py[i];
                sx = t * ux;
                sy = t * uy;
            }
        }
        for (int e = 0; e < 2; e++) {
            float ex = e * length * ux;
            float ey = e * length * uy;
            for (int i = 0, k = n - 1; i < n; k = i++) {
                float fx = px[i] - px[k];
                float fy = py[i] - py[k];
                float t = ((ex - px[k]) * fx + (ey - py[k]) * fy) / (fx * fx + fy * fy);
                t = t < 0f ? 0f : (t > 1f ? 1f : t);
                float dx = px[k] + t * fx - ex;
                float dy = py[k] + t * fy - ey;
                float d2 = dx * dx + dy * dy;
                if (d2 < best) {
                    best = d2;
                    interior = false;
                    end = e;
                    feature = k;
                    qx = px[k] + t * fx;
                    qy = py[k] + t * fy;
                    sx = ex;
                    sy = ey;
                }
            }
        }
        float distance = EMath.sqrt(best);
        if (distance > speculativeDistance || !(distance > 0f)) {
            return;
        }
        float mx = (qx - sx) / distance;
        float my = (qy - sy) / distance;
        if (interior && mx * nx + my * ny <= 0f) {
            return;
        }
        if (interior || !admissible(mx, my)) {
            // A face contact: the polygon's incident edge clipped to the segment, along n. Also
            // when the closest end may not give the normal (the polygon turning towards a joint
            // the neighbour owns): the gaps along n still keep it from sweeping through the face.
            overlapping(seg, b, bx, by, bc, bs, 0, speculativeDistance, out);
            // Clipping reports gaps no smaller than the closest distance unless the incident edge
            // lies beside the face, where it falls back to a depth: then it is not trusted.
            boolean trusted = out.pointCount > 0;
            for (int k = 0; k < out.pointCount; k++) {
                trusted &= out.separation[k] >= distance - CLOSE_TOLERANCE;
            }
            if (trusted || !interior) {
                if (!trusted) {
                    out.pointCount = 0;
                }
                return;
            }
            mx = nx;
            my = ny;
        }
        writeOnePoint(mx, my, seg.x1 + 0.5f * (sx + qx), seg.y1 + 0.5f * (sy + qy), distance, out);
        // Ids as the clipping numbers them: the end the segment-as-polygon starts at is 0.
        boolean forward = nx * uy - ny * ux > 0f;
        out.id[0] = ((forward ? end : 1 - end) << 8) | feature;
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
