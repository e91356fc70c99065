package org.emini.shape;

import org.emini.math.EMath;
import org.emini.shape.InvalidShapeException.Rule;

/**
 * Validates and cleans the coordinates given to {@link Polygon#Polygon(float...)}.
 *
 * <p>Steps, in order: all coordinates finite; near-duplicate consecutive vertices merged;
 * at least three distinct vertices; not all on one line; collinear vertices removed; convex;
 * simple; at most {@link Shape#MAX_VERTICES} vertices; at least {@link Shape#MIN_SIZE} across. Lengths are compared with
 * {@link Polygon#RELATIVE_TOLERANCE} × size, size being the larger side of the input's bounding
 * box, so the result does not depend on the unit of length.
 */
final class PolygonCleaner {
    private PolygonCleaner() {
    }

    /**
     * Returns the cleaned polygon as x0, y0, x1, y1, ... in counter-clockwise order (positive
     * signed area), or throws.
     */
    static float[] clean(float[] xy) {
        if (xy == null) {
            throw new IllegalArgumentException("Polygon: the coordinate array is null");
        }
        if (xy.length % 2 != 0) {
            throw new IllegalArgumentException("Polygon: odd number of coordinates (" + xy.length
                    + "); expected x0, y0, x1, y1, ...");
        }
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            if (!EMath.isFinite(xy[2 * i]) || !EMath.isFinite(xy[2 * i + 1])) {
                throw fail(Rule.NOT_FINITE, i, xy[2 * i], xy[2 * i + 1],
                        "has a coordinate that is NaN or infinite");
            }
        }
        if (n < 3) {
            throw new InvalidShapeException(Rule.TOO_FEW_VERTICES, -1, "Polygon: rule "
                    + Rule.TOO_FEW_VERTICES + ": " + n + " vertices given, at least 3 needed");
        }

        float minX = xy[0];
        float maxX = xy[0];
        float minY = xy[1];
        float maxY = xy[1];
        for (int i = 1; i < n; i++) {
            minX = Math.min(minX, xy[2 * i]);
            maxX = Math.max(maxX, xy[2 * i]);
            minY = Math.min(minY, xy[2 * i + 1]);
            maxY = Math.max(maxY, xy[2 * i + 1]);
        }
        float size = Math.max(maxX - minX, maxY - minY);
        float tol = Polygon.RELATIVE_TOLERANCE * size;
        float tol2 = tol * tol;

        // Working copy; index[] remembers each vertex's position in the caller's input.
        float[] px = new float[n];
        float[] py = new float[n];
        int[] index = new int[n];
        int m = 0;
        int merged = -1;
        for (int i = 0; i < n; i++) {
            float x = xy[2 * i];
            float y = xy[2 * i + 1];
            if (m > 0 && dist2(px[m - 1], py[m - 1], x, y) <= tol2) {
                merged = i;
                continue;
            }
            px[m] = x;
            py[m] = y;
            index[m] = i;
            m++;
        }
        while (m > 1 && dist2(px[m - 1], py[m - 1], px[0], py[0]) <= tol2) {
            merged = index[m - 1];
            m--;
        }
        if (m < 3) {
            throw fail(Rule.TOO_FEW_VERTICES, merged, xy[2 * merged], xy[2 * merged + 1],
                    "coincides with its neighbour (closer than " + Polygon.RELATIVE_TOLERANCE
                            + " x size " + size + "); only " + m
                            + " distinct vertices remain, at least 3 needed");
        }

        checkNotOnOneLine(px, py, index, m, tol);
        m = removeCollinear(px, py, index, m, tol2);

        // Turns: cross and dot of consecutive edges at each vertex.
        int positive = 0;
        int negative = 0;
        for (int i = 0; i < m; i++) {
            if (turnCross(px, py, m, i) > 0f) {
                positive++;
            } else {
                negative++;
            }
        }
        if (positive > 0 && negative > 0) {
            boolean majorityPositive = positive >= negative;
            for (int i = 0; i < m; i++) {
                if ((turnCross(px, py, m, i) > 0f) != majorityPositive) {
                    throw fail(Rule.NOT_CONVEX, index[i], px[i], py[i],
                            "turns the other way from the rest of the outline: the polygon has"
                                    + " a recess there");
                }
            }
        }
        checkSimple(px, py, index, m);

        float twiceArea = 0f;
        for (int i = 0; i < m; i++) {
            int k = i + 1 == m ? 0 : i + 1;
            twiceArea += (px[i] - px[0]) * (py[k] - py[0]) - (px[k] - px[0]) * (py[i] - py[0]);
        }
        float area = 0.5f * Math.abs(twiceArea);
        // Safety net for rounding: the steps above already keep every vertex tol off its chord.
        if (area <= 0.25f * tol * size) {
            throw new InvalidShapeException(Rule.DEGENERATE, -1, "Polygon: rule "
                    + Rule.DEGENERATE + ": area " + area + " is about zero");
        }
        if (m > Shape.MAX_VERTICES) {
            // Cleaning keeps the caller's order, so the 13th remaining vertex is the first extra.
            int first = Shape.MAX_VERTICES;
            throw fail(Rule.TOO_MANY_VERTICES, index[first], px[first], py[first],
                    "is one too many: " + m + " vertices remain after cleaning, at most "
                            + Shape.MAX_VERTICES + " allowed");
        }
        float width = narrowestWidth(px, py, m);
        if (width < Shape.MIN_SIZE) {
            throw new InvalidShapeException(Rule.TOO_SMALL, -1, "Polygon: rule " + Rule.TOO_SMALL + ": it is "
                    + width + " px across at its narrowest, below Shape.MIN_SIZE (" + Shape.MIN_SIZE + " px)");
        }
        if (negative > 0) {
            reverse(px, py, index, m);
        }

        float[] out = new float[2 * m];
        for (int i = 0; i < m; i++) {
            out[2 * i] = px[i];
            out[2 * i + 1] = py[i];
        }
        return out;
    }

    /**
     * The width of a convex polygon where it is narrowest: the least, over its edges, of the
     * farthest vertex's distance from the edge's line (the narrowest direction is an edge normal).
     */
    private static float narrowestWidth(float[] px, float[] py, int m) {
        float narrowest = Float.MAX_VALUE;
        for (int i = 0; i < m; i++) {
            int k = i + 1 == m ? 0 : i + 1;
            float ex = px[k] - px[i];
            float ey = py[k] - py[i];
            float far = 0f;
            for (int j = 0; j < m; j++) {
                far = Math.max(far, Math.abs(ex * (py[j] - py[i]) - ey * (px[j] - px[i])));
            }
            narrowest = Math.min(narrowest, far / EMath.sqrt(ex * ex + ey * ey));
        }
        return narrowest;
    }

    /** Refuses a vertex set that lies within tol of one line (no area). */
    private static void checkNotOnOneLine(float[] px, float[] py, int[] index, int m, float tol) {
        int far = 0;
        float far2 = 0f;
        for (int k = 1; k < m; k++) {
            float d2 = dist2(px[0], py[0], px[k], py[k]);
            if (d2 > far2) {
                far2 = d2;
                far = k;
            }
        }
        float lx = px[far] - px[0];
        float ly = py[far] - py[0];
        float len = EMath.sqrt(far2);
        int off = 0;
        float offDist = 0f;
        for (int k = 1; k < m; k++) {
            float d = Math.abs(lx * (py[k] - py[0]) - ly * (px[k] - px[0])) / len;
            if (d > offDist) {
                offDist = d;
                off = k;
            }
        }
        if (offDist <= tol) {
            throw fail(Rule.DEGENERATE, index[off], px[off], py[off],
                    "is the farthest from the line through vertices " + index[0] + " and "
                            + index[far] + ", only " + offDist
                            + " away: all vertices lie on one line and the polygon has no area");
        }
    }

    /**
     * Removes vertices that lie within tol of the segment joining their neighbours; refuses a
     * vertex on that line but outside the segment, where the outline doubles back. Returns the
     * new count.
     */
    private static int removeCollinear(float[] px, float[] py, int[] index, int m, float tol2) {
        boolean removed = true;
        while (removed && m >= 3) {
            removed = false;
            int i = 0;
            while (i < m && m >= 3) {
                int ip = i == 0 ? m - 1 : i - 1;
                int in = i + 1 == m ? 0 : i + 1;
                float ex = px[in] - px[ip];
                float ey = py[in] - py[ip];
                float vx = px[i] - px[ip];
                float vy = py[i] - py[ip];
                float cross = ex * vy - ey * vx;
                // |cross| / |chord| is the distance from the chord's line; compared squared.
                if (cross * cross <= tol2 * (ex * ex + ey * ey)) {
                    float wx = px[in] - px[i];
                    float wy = py[in] - py[i];
                    if (vx * wx + vy * wy <= 0f) {
                        throw fail(Rule.SELF_INTERSECTING, index[i], px[i], py[i],
                                "lies on the line through its neighbours but not between them:"
                                        + " the outline doubles back on itself");
                    }
                    System.arraycopy(px, i + 1, px, i, m - i - 1);
                    System.arraycopy(py, i + 1, py, i, m - i - 1);
                    System.arraycopy(index, i + 1, index, i, m - i - 1);
                    m--;
                    removed = true;
                } else {
                    i++;
                }
            }
        }
        if (m < 3) {
            throw new InvalidShapeException(Rule.DEGENERATE, -1, "Polygon: rule "
                    + Rule.DEGENERATE + ": fewer than 3 vertices remain after removing collinear"
                    + " ones");
        }
        return m;
    }

    /** Refuses an outline whose turns (all one way) add up to more than one full turn. */
    private static void checkSimple(float[] px, float[] py, int[] index, int m) {
        float total = 0f;
        for (int i = 0; i < m; i++) {
            total += turnAngle(px, py, m, i);
        }
        if (Math.abs(total) < 3f * EMath.PI) {
            return;
        }
        float sum = 0f;
        for (int i = 0; i < m; i++) {
            sum += turnAngle(px, py, m, i);
            if (Math.abs(sum) > EMath.TWO_PI) {
                throw fail(Rule.SELF_INTERSECTING, index[i], px[i], py[i],
                        "completes the outline's first full turn, yet the outline turns "
                                + Math.round(Math.abs(total) * 180f / EMath.PI)
                                + " degrees in all: it winds around more than once and crosses"
                                + " itself");
            }
        }
    }

    private static float turnCross(float[] px, float[] py, int m, int i) {
        int ip = i == 0 ? m - 1 : i - 1;
        int in = i + 1 == m ? 0 : i + 1;
        return (px[i] - px[ip]) * (py[in] - py[i]) - (py[i] - py[ip]) * (px[in] - px[i]);
    }

    private static float turnAngle(float[] px, float[] py, int m, int i) {
        int ip = i == 0 ? m - 1 : i - 1;
        int in = i + 1 == m ? 0 : i + 1;
        float ax = px[i] - px[ip];
        float ay = py[i] - py[ip];
        float bx = px[in] - px[i];
        float by = py[in] - py[i];
        return EMath.atan2(ax * by - ay * bx, ax * bx + ay * by);
    }

    private static void reverse(float[] px, float[] py, int[] index, int m) {
        for (int i = 0, j = m - 1; i < j; i++, j--) {
            float tx = px[i];
            px[i] = px[j];
            px[j] = tx;
            float ty = py[i];
            py[i] = py[j];
            py[j] = ty;
            int ti = index[i];
            index[i] = index[j];
            index[j] = ti;
        }
    }

    private static float dist2(float ax, float ay, float bx, float by) {
        float dx = bx - ax;
        float dy = by - ay;
        return dx * dx + dy * dy;
    }

    private static InvalidShapeException fail(Rule rule, int index, float x, float y,
            String problem) {
        return new InvalidShapeException(rule, index, "Polygon: rule " + rule + ": vertex "
                + index + " at (" + x + ", " + y + ") " + problem);
    }
}
