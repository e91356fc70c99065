package org.emini.collision;

import org.emini.math.EMath;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * Polygon–polygon narrowphase: separating axes over both polygons' face normals, then the
 * incident edge clipped against the reference face (Sutherland–Hodgman on two side planes).
 *
 * <p>Everything is computed in A's local frame (B is brought into it), which keeps coordinates
 * small however far the pair is from the world origin. The scratch arrays are reused by every
 * call; nothing is allocated.
 */
final class PolygonCollider {
    // Relative to the smaller polygon's bounding radius: how much more B's face must separate
    // than A's to become the reference, and the smallest incident-edge overlap with the
    // reference face that still counts as two distinct points.
    static final float LINEAR_TOLERANCE = 1e-3f;
    // Face mask that tries every face.
    static final int ALL_FACES = -1;

    private final float[] ax = new float[Shape.MAX_VERTICES];
    private final float[] ay = new float[Shape.MAX_VERTICES];
    private final float[] anx = new float[Shape.MAX_VERTICES];
    private final float[] any = new float[Shape.MAX_VERTICES];
    private final float[] bx = new float[Shape.MAX_VERTICES];
    private final float[] by = new float[Shape.MAX_VERTICES];
    private final float[] bnx = new float[Shape.MAX_VERTICES];
    private final float[] bny = new float[Shape.MAX_VERTICES];

    /** Edge index found by the last {@link #maxSeparation} call. */
    private int foundEdge;
    /**
     * After a {@link #collide} that found the polygons apart: the largest separation of B from one
     * of A's faces (in A's frame, where A's faces stay put); negative infinity otherwise.
     */
    float apartGap;

    void collide(Polygon a, float pax, float pay, float ac, float as, Polygon b, float pbx,
            float pby, float bc, float bs, float speculativeDistance, Manifold out) {
        apartGap = Float.NEGATIVE_INFINITY;
        int na = a.getVertexCount();
        int nb = b.getVertexCount();
        for (int i = 0; i < na; i++) {
            ax[i] = a.getVertexX(i);
            ay[i] = a.getVertexY(i);
            anx[i] = a.getNormalX(i);
            any[i] = a.getNormalY(i);
        }
        // B's pose relative to A: rotation by θB − θA, translation RAᵀ (pB − pA).
        float rc = ac * bc + as * bs;
        float rs = ac * bs - as * bc;
        float dx = pbx - pax;
        float dy = pby - pay;
        float tx = ac * dx + as * dy;
        float ty = -as * dx + ac * dy;
        for (int j = 0; j < nb; j++) {
            float x = b.getVertexX(j);
            float y = b.getVertexY(j);
            bx[j] = rc * x - rs * y + tx;
            by[j] = rs * x + rc * y + ty;
            float nx = b.getNormalX(j);
            float ny = b.getNormalY(j);
            bnx[j] = rc * nx - rs * ny;
            bny[j] = rs * nx + rc * ny;
        }

        if (!separateAndClip(na, na, nb, ALL_FACES, a.getBoundingRadius(), b.getBoundingRadius(),
                speculativeDistance, out)) {
            return;
        }
        // A's frame to the world.
        float nx = out.normalX;
        float ny = out.normalY;
        out.normalX = ac * nx - as * ny;
        out.normalY = as * nx + ac * ny;
        for (int k = 0; k < out.pointCount; k++) {
            float x = out.pointX[k];
            float y = out.pointY[k];
            out.pointX[k] = pax + ac * x - as * y;
            out.pointY[k] = pay + as * x + ac * y;
        }
    }

    /**
     * Collides a one-sided segment A with a polygon B, in a frame with B's position as origin and
     * the world's axes. A is the two-vertex polygon (x1, y1), (x2, y2) whose first face has the
     * outward unit normal (nx, ny): only that face is tried as a separating axis, and only B's faces
     * whose bit is set in admissible, so the normal never points where the caller forbids it. The
     * caller handles a polygon lying wholly beyond an end of the segment, where the test on these
     * axes alone could report an overlap that is not there.
     * Vertex ids name A's vertices 0 (first given) and 1. The result is in the world.
     */
    void collideSegment(float x1, float y1, float x2, float y2, float nx, float ny,
            Polygon b, float pbx, float pby, float bc, float bs, int admissible,
            float speculativeDistance, Manifold out) {
        ax[0] = x1 - pbx;
        ay[0] = y1 - pby;
        ax[1] = x2 - pbx;
        ay[1] = y2 - pby;
        anx[0] = nx;
        any[0] = ny;
        anx[1] = -nx;
        any[1] = -ny;
        int nb = b.getVertexCount();
        for (int j = 0; j < nb; j++) {
            float x = b.getVertexX(j);
            float y = b.getVertexY(j);
            bx[j] = bc * x - bs * y;
            by[j] = bs * x + bc * y;
            float mx = b.getNormalX(j);
            float my = b.getNormalY(j);
            bnx[j] = bc * mx - bs * my;
            bny[j] = bs * mx + bc * my;
        }
        float ex = x2 - x1;
        float ey = y2 - y1;
        float halfLength = 0.5f * EMath.sqrt(ex * ex + ey * ey);
        if (!separateAndClip(2, 1, nb, admissible, halfLength, b.getBoundingRadius(),
                speculativeDistance, out)) {
            return;
        }
        for (int k = 0; k < out.pointCount; k++) {
            out.pointX[k] += pbx;
            out.pointY[k] += pby;
        }
    }

    /**
     * The separating-axis test and clipping on the scratch arrays, in A's frame: A has na vertices
     * of which the first facesA faces are tried, B has nb vertices of which the faces set in
     * facesB are tried. Returns false (and no points) when the shapes are farther apart than the
     * speculative distance.
     */
    private boolean separateAndClip(int na, int facesA, int nb, int facesB, float ra, float rb,
            float speculativeDistance, Manifold out) {
        float sepA = maxSeparation(ax, ay, anx, any, facesA, ALL_FACES, bx, by, nb);
        int edgeA = foundEdge;
        float sepB = maxSeparation(bx, by, bnx, bny, nb, facesB, ax, ay, na);
        int edgeB = foundEdge;
        if (sepA > speculativeDistance || sepB > speculativeDistance) {
            apartGap = sepA;
            out.pointCount = 0;
            return false;
        }
        float tol = LINEAR_TOLERANCE * (ra < rb ? ra : rb);
        // Prefer A within the tolerance, but never pick a face that does not separate the shapes
        // over one that does: then every reported gap is a true distance to the reference shape.
        boolean flip = sepB > sepA + tol || (sepB > 0f && sepA <= 0f);
        if (flip) {
            clip(bx, by, bnx, bny, nb, edgeB, sepB, ax, ay, anx, any, na, true, tol,
                    speculativeDistance, out);
        } else {
            clip(ax, ay, anx, any, na, edgeA, sepA, bx, by, bnx, bny, nb, false, tol,
                    speculativeDistance, out);
        }
        return out.pointCount > 0;
    }

    /**
     * The largest separation of polygon 2 from a face of polygon 1: for each of the first n1 faces
     * whose bit is set in faces, the signed distance of polygon 2's deepest vertex; the face index
     * goes to {@link #foundEdge}. Negative infinity when no face is tried.
     */
    private float maxSeparation(float[] x1, float[] y1, float[] nx1, float[] ny1, int n1,
            int faces, float[] x2, float[] y2, int n2) {
        int best = 0;
        float bestSeparation = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < n1; i++) {
            if ((faces & (1 << i)) == 0) {
                continue;
            }
            float nx = nx1[i];
            float ny = ny1[i];
            float vx = x1[i];
            float vy = y1[i];
            float deepest = Float.POSITIVE_INFINITY;
            for (int j = 0; j < n2; j++) {
                float s = nx * (x2[j] - vx) + ny * (y2[j] - vy);
                if (s < deepest) {
                    deepest = s;
                }
            }
            if (deepest > bestSeparation) {
                bestSeparation = deepest;
                best = i;
            }
        }
        foundEdge = best;
        return bestSeparation;
    }

    /**
     * Builds the manifold (in A's frame) from a reference face of polygon R and the incident edge
     * of polygon I; flip says R is B. Every point of I lies at least sepRef in front of the face.
     */
    private static void clip(float[] rx, float[] ry, float[] rnx, float[] rny, int rn, int r1,
            float sepRef, float[] ix, float[] iy, float[] inx, float[] iny, int in,
            boolean flip, float tol, float speculativeDistance, Manifold out) {
        int r2 = r1 + 1 == rn ? 0 : r1 + 1;
        float nx = rnx[r1];
        float ny = rny[r1];

        // Incident edge: the one whose normal is most anti-parallel to the reference normal.
        int i1 = 0;
        float minDot = Float.POSITIVE_INFINITY;
        for (int j = 0; j < in; j++) {
            float d = nx * inx[j] + ny * iny[j];
            if (d < minDot) {
                minDot = d;
                i1 = j;
            }
        }
        int i2 = i1 + 1 == in ? 0 : i1 + 1;

        // Coordinates along the reference face, from r1 (0) towards r2 (upper1). Both polygons
        // wind counter-clockwise, so the incident edge runs the other way: i1 high, i2 low.
        float tx = -ny;
        float ty = nx;
        float ox = rx[r1];
        float oy = ry[r1];
        float upper1 = tx * (rx[r2] - ox) + ty * (ry[r2] - oy);
        float upper2 = tx * (ix[i1] - ox) + ty * (iy[i1] - oy);
        float lower2 = tx * (ix[i2] - ox) + ty * (iy[i2] - oy);
        float span = upper2 - lower2;

        if (upper2 < 0f || lower2 > upper1 || span <= tol) {
            beside(rx, ry, r1, r2, nx, ny, sepRef, ix, iy, i1, i2, upper2 < 0f,
                    lower2 > upper1, flip, speculativeDistance, out);
            return;
        }

        // Clip the incident edge to the face's side planes at 0 and upper1.
        float lowT = lower2 < 0f ? (0f - lower2) / span : 0f;
        float highT = upper2 > upper1 ? (upper1 - lower2) / span : 1f;
        float ex = ix[i1] - ix[i2];
        float ey = iy[i1] - iy[i2];
        float lowX = ix[i2] + lowT * ex;
        float lowY = iy[i2] + lowT * ey;
        float highX = ix[i2] + highT * ex;
        float highY = iy[i2] + highT * ey;
        float lowSep = nx * (lowX - ox) + ny * (lowY - oy);
        float highSep = nx * (highX - ox) + ny * (highY - oy);

        int count = 0;
        // Two points closer than tol along the face would make the solver's 2×2 block
        // ill-conditioned; keep only the deeper one.
        boolean distinct = (highT - lowT) * span > tol;
        boolean keepLow = lowSep <= speculativeDistance && (distinct || lowSep <= highSep);
        boolean keepHigh = highSep <= speculativeDistance && (distinct || highSep < lowSep);
        if (keepLow) {
            count = addPoint(out, count, lowX, lowY, lowSep, nx, ny, r1, i2, flip);
        }
        if (keepHigh) {
            count = addPoint(out, count, highX, highY, highSep, nx, ny, r2, i1, flip);
        }
        out.pointCount = count;
        if (count > 0) {
            setNormal(out, nx, ny, flip);
        }
    }

    /**
     * The incident edge does not overlap the reference face along the face (or is too short
     * across it): one point. When the shapes are apart the point joins the face's end vertex to
     * the nearest point of the incident edge, with that direction as the normal (a true distance,
     * unlike the face separation); when they overlap it is the deepest incident vertex.
     */
    private static void beside(float[] rx, float[] ry, int r1, int r2, float nx, float ny,
            float sepRef, float[] ix, float[] iy, int i1, int i2, boolean belowR1,
            boolean aboveR2, boolean flip, float speculativeDistance, Manifold out) {
        int rv = aboveR2 ? r2 : r1;
        float vx = rx[rv];
        float vy = ry[rv];
        if (sepRef > 0f && (belowR1 || aboveR2)) {
            float ex = ix[i1] - ix[i2];
            float ey = iy[i1] - iy[i2];
            float t = ((vx - ix[i2]) * ex + (vy - iy[i2]) * ey) / (ex * ex + ey * ey);
            t = t < 0f ? 0f : (t > 1f ? 1f : t);
            float qx = ix[i2] + t * ex;
            float qy = iy[i2] + t * ey;
            float dx = qx - vx;
            float dy = qy - vy;
            float distance = EMath.sqrt(dx * dx + dy * dy);
            if (distance > speculativeDistance) {
                out.pointCount = 0;
                return;
            }
            if (distance > 0f) {
                nx = dx / distance;
                ny = dy / distance;
            }
            // Pair the reference vertex with the incident vertex on the same side.
            int iv = belowR1 ? i1 : i2;
            out.pointCount = addPoint(out, 0, qx, qy, distance, nx, ny, rv, iv, flip);
            setNormal(out, nx, ny, flip);
            return;
        }
        float s1 = nx * (ix[i1] - vx) + ny * (iy[i1] - vy);
        float s2 = nx * (ix[i2] - vx) + ny * (iy[i2] - vy);
        int iv = s1 <= s2 ? i1 : i2;
        float s = s1 <= s2 ? s1 : s2;
        if (s > speculativeDistance) {
            out.pointCount = 0;
            return;
        }
        out.pointCount = addPoint(out, 0, ix[iv], iy[iv], s, nx, ny, rv, iv, flip);
        setNormal(out, nx, ny, flip);
    }

    /**
     * Stores a point of the incident polygon, moved halfway back to the reference surface along
     * the normal (nx, ny), with its key in A/B order.
     */
    private static int addPoint(Manifold out, int k, float x, float y, float separation,
            float nx, float ny, int refVertex, int incVertex, boolean flip) {
        out.pointX[k] = x - 0.5f * separation * nx;
        out.pointY[k] = y - 0.5f * separation * ny;
        out.separation[k] = separation;
        out.id[k] = flip ? (incVertex << 8) | refVertex : (refVertex << 8) | incVertex;
        return k + 1;
    }

    /** The normal points from the reference to the incident polygon; the manifold's from A to B. */
    private static void setNormal(Manifold out, float nx, float ny, boolean flip) {
        out.normalX = flip ? -nx : nx;
        out.normalY = flip ? -ny : ny;
    }
}
