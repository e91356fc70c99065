package org.emini.shape;

import org.emini.math.EMath;

/**
 * A convex polygon of 3 to {@link Shape#MAX_VERTICES} vertices, stored counter-clockwise in math
 * orientation: cross(v1 − v0, v2 − v1) &gt; 0 and the signed area is positive. (On a y-down
 * screen that order looks clockwise.)
 *
 * <p>The polygon need not be centred: the body rotates about the local origin, and the inertia is
 * the polar moment of the area about that origin scaled to the mass (uniform density). Use
 * {@link #centred()} for the original designer's "centroid correction".
 */
public final class Polygon extends Shape {
    /**
     * Lengths below this fraction of the polygon's size (the larger side of the input's bounding
     * box) count as zero when cleaning the input: nearer vertices are merged, and a vertex nearer
     * than that to the line through its neighbours is removed as collinear.
     */
    public static final float RELATIVE_TOLERANCE = 1e-4f;

    private final float[] vx;
    private final float[] vy;
    private final float[] nx;
    private final float[] ny;

    /**
     * Creates a convex polygon from local coordinates, validating and cleaning them in this order:
     * <ol>
     * <li>every coordinate finite ({@link InvalidShapeException.Rule#NOT_FINITE});</li>
     * <li>consecutive vertices closer than {@link #RELATIVE_TOLERANCE} × size merged, keeping the
     * first; at least 3 must remain ({@link InvalidShapeException.Rule#TOO_FEW_VERTICES});</li>
     * <li>not all vertices on one line ({@link InvalidShapeException.Rule#DEGENERATE});</li>
     * <li>collinear vertices removed (collinear faces only cost time in collision tests); a vertex
     * on the line through its neighbours but outside them, where the outline doubles back, is
     * refused ({@link InvalidShapeException.Rule#SELF_INTERSECTING});</li>
     * <li>convex: every turn goes the same way ({@link InvalidShapeException.Rule#NOT_CONVEX});</li>
     * <li>simple: the turns add up to exactly one full turn, so a pentagram is refused
     * ({@link InvalidShapeException.Rule#SELF_INTERSECTING});</li>
     * <li>area not about zero ({@link InvalidShapeException.Rule#DEGENERATE});</li>
     * <li>at most {@link Shape#MAX_VERTICES} vertices remain
     * ({@link InvalidShapeException.Rule#TOO_MANY_VERTICES}).</li>
     * </ol>
     * Either winding is accepted; the vertices are stored counter-clockwise (positive area).
     *
     * @param xy the coordinates x0, y0, x1, y1, ... (px)
     * @throws InvalidShapeException if a rule above is broken; the message names the rule and
     *     the offending vertex (its index in xy, counting pairs) with its coordinates
     * @throws IllegalArgumentException if xy is null or has an odd length
     */
    public Polygon(float... xy) {
        this(ShapeGeometry.ofPolygon(PolygonCleaner.clean(xy)));
    }

    private Polygon(ShapeGeometry geometry) {
        super(geometry, TYPE_POLYGON);
        float[] ccw = geometry.vertices;
        int n = ccw.length / 2;
        vx = new float[n];
        vy = new float[n];
        nx = new float[n];
        ny = new float[n];
        for (int i = 0; i < n; i++) {
            vx[i] = ccw[2 * i];
            vy[i] = ccw[2 * i + 1];
        }
        for (int i = 0; i < n; i++) {
            int k = i + 1 == n ? 0 : i + 1;
            float ex = vx[k] - vx[i];
            float ey = vy[k] - vy[i];
            float inv = 1f / EMath.sqrt(ex * ex + ey * ey);
            // Counter-clockwise order puts the outside on the right of each edge.
            nx[i] = ey * inv;
            ny[i] = -ex * inv;
        }
    }

    /**
     * The number of vertices after cleaning.
     *
     * @return 3 to {@link Shape#MAX_VERTICES}
     */
    public int getVertexCount() {
        return vx.length;
    }

    /**
     * The local x of a vertex.
     *
     * @param i the vertex index, 0 to {@link #getVertexCount()} − 1
     * @return the x (px)
     */
    public float getVertexX(int i) {
        return vx[i];
    }

    /**
     * The local y of a vertex.
     *
     * @param i the vertex index, 0 to {@link #getVertexCount()} − 1
     * @return the y (px)
     */
    public float getVertexY(int i) {
        return vy[i];
    }

    /**
     * The local x of the outward unit normal of the edge from vertex i to vertex i + 1 (the last
     * edge wraps to vertex 0).
     *
     * @param i the edge index, 0 to {@link #getVertexCount()} − 1
     * @return the normal's x
     */
    public float getNormalX(int i) {
        return nx[i];
    }

    /**
     * The local y of the outward unit normal of the edge from vertex i to vertex i + 1.
     *
     * @param i the edge index, 0 to {@link #getVertexCount()} − 1
     * @return the normal's y
     */
    public float getNormalY(int i) {
        return ny[i];
    }

    /**
     * A copy translated so that its centroid is at the local origin, with the same mass, friction
     * and elasticity. Its inertia is smaller by mass·|centroid|².
     *
     * @return the centred polygon
     */
    public Polygon centred() {
        return translated(-getCentroidX(), -getCentroidY());
    }

    @Override
    Polygon translated(float dx, float dy) {
        float[] xy = new float[2 * vx.length];
        for (int i = 0; i < vx.length; i++) {
            xy[2 * i] = vx[i] + dx;
            xy[2 * i + 1] = vy[i] + dy;
        }
        // A translated valid polygon stays valid: no second cleaning, which could round differently.
        Polygon p = new Polygon(ShapeGeometry.ofPolygon(xy));
        p.copyMaterial(this);
        return p;
    }

    @Override
    public void computeAabb(float x, float y, float c, float s, float[] out) {
        float minX = Float.POSITIVE_INFINITY;
        float minY = Float.POSITIVE_INFINITY;
        float maxX = Float.NEGATIVE_INFINITY;
        float maxY = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < vx.length; i++) {
            float wx = x + c * vx[i] - s * vy[i];
            float wy = y + s * vx[i] + c * vy[i];
            if (wx < minX) {
                minX = wx;
            }
            if (wx > maxX) {
                maxX = wx;
            }
            if (wy < minY) {
                minY = wy;
            }
            if (wy > maxY) {
                maxY = wy;
            }
        }
        out[0] = minX;
        out[1] = minY;
        out[2] = maxX;
        out[3] = maxY;
    }

    @Override
    public String toString() {
        StringBuilder b = new StringBuilder("Polygon[");
        for (int i = 0; i < vx.length; i++) {
            b.append(i == 0 ? "(" : ", (").append(vx[i]).append(", ").append(vy[i]).append(')');
        }
        return b.append(", mass ").append(getMass()).append(']').toString();
    }
}
