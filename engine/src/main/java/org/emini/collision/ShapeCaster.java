package org.emini.collision;

import org.emini.math.EMath;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * A shape swept along a straight translation (no rotation) against a fixed shape or a line
 * segment: the first moment they touch, exactly, not by iteration.
 *
 * <p>Under a translation the first contact of two convex parts is a vertex of one meeting a face
 * of the other, or, where a circle is involved, a ray against a polygon grown by the radius (its
 * faces pushed out, its corners rounded). Every such feature pair is solved in closed form and the
 * earliest wins; a multi-shape is taken part by part. The result, in the public fields, is the
 * fraction {@link #t} of the translation at which the parts first touch, the contact point
 * ({@link #x}, {@link #y}) in the world at that moment, and the unit normal ({@link #normalX},
 * {@link #normalY}) of the fixed shape's surface there, pointing from the fixed shape to the moving
 * one. Shapes are closed: touching is a hit, and a pass that only grazes a corner hits it.
 *
 * <p>Parts that already overlap or touch where the sweep starts hit at t = 0, with
 * {@link #overlapping} set; the normal is then the shortest way out for the moving part (the
 * separating axis of least overlap) and the point the moving part's deepest point along it. So a
 * zero translation is an exact overlap test.
 *
 * <p>Accuracy: float arithmetic in a frame at the fixed shape's origin; a face is stretched at
 * its ends by a few float roundings of the coordinates involved so that a vertex meeting a vertex
 * head-on is never lost between the two faces, so a pass that clears a corner by less than about
 * 10⁻⁶ of the coordinates' size may count as a hit. No allocation; not thread-safe (one instance
 * per user).
 */
public final class ShapeCaster {
    private static final int MAX = Shape.MAX_VERTICES;
    // Faces are stretched by this fraction of their length and of the coordinates' size.
    private static final float STRETCH = 1e-5f;
    private static final float ROUNDING = 4e-7f;

    /** The fraction of the translation at the first contact, in [0, 1]. */
    public float t;
    /** The world x of the contact point at that moment (px). */
    public float x;
    /** The world y of the contact point (px). */
    public float y;
    /** The x of the unit normal, from the fixed shape to the moving one. */
    public float normalX;
    /** The y of the unit normal. */
    public float normalY;
    /** The part of the fixed shape hit (its index in a multi-shape), 0 for other shapes and segments. */
    public int part;
    /** Whether the hit is an overlap (or touch) where the sweep starts. */
    public boolean overlapping;

    // The moving part (A) at the start and the fixed part (B), relative to (ox, oy): vertices,
    // outward normals of the faces v[i] -> v[i + 1], and a radius (a circle: one vertex).
    private final float[] avx = new float[MAX];
    private final float[] avy = new float[MAX];
    private final float[] anx = new float[MAX];
    private final float[] any = new float[MAX];
    private int an;
    private float ar;
    private final float[] bvx = new float[MAX];
    private final float[] bvy = new float[MAX];
    private final float[] bnx = new float[MAX];
    private final float[] bny = new float[MAX];
    private int bn;
    private float br;
    private float ox;
    private float oy;
    // The translation and the size of the coordinates in the frame (for the stretch).
    private float dx;
    private float dy;
    private float scale;

    // The best hit of the current query, relative to (ox, oy).
    private float bestT;
    private float bestX;
    private float bestY;
    private float bestNx;
    private float bestNy;
    private boolean bestOverlap;
    // A candidate from rounded(): its outward normal and contact point on the core.
    private float candNx;
    private float candNy;
    private float candX;
    private float candY;
    // The separating axis found by separation().
    private float axisX;
    private float axisY;

    /** Creates a shape caster. */
    public ShapeCaster() {
    }

    /**
     * Sweeps a shape along a translation against a fixed shape; multi-shapes on either side part
     * by part (the earliest part pair wins, the first on a tie).
     *
     * @param moving the moving shape
     * @param mx its x at the start (px)
     * @param my its y at the start (px)
     * @param mc cos of its angle
     * @param ms sin of its angle
     * @param dx the translation's x (px)
     * @param dy the translation's y (px)
     * @param fixed the fixed shape
     * @param fx its x (px)
     * @param fy its y (px)
     * @param fc cos of its angle
     * @param fs sin of its angle
     * @return whether the moving shape touches the fixed one during the sweep; the fields hold the
     *     first contact when it does
     */
    public boolean cast(Shape moving, float mx, float my, float mc, float ms, float dx, float dy,
            Shape fixed, float fx, float fy, float fc, float fs) {
        begin(fx, fy, dx, dy);
        int nf = fixed.getType() == Shape.TYPE_MULTI ? ((MultiShape) fixed).getShapeCount() : 1;
        for (int j = 0; j < nf; j++) {
            Shape pf = fixed.getType() == Shape.TYPE_MULTI ? ((MultiShape) fixed).getShape(j) : fixed;
            float before = bestT;
            loadFixed(pf, fx, fy, fc, fs);
            castMoving(moving, mx, my, mc, ms);
            if (bestT < before) {
                part = j;
            }
        }
        return finish();
    }

    /**
     * Sweeps a shape along a translation against a line segment, solid from both sides here (the
     * caller decides whether a faced landscape segment stops the shape at all).
     *
     * @param moving the moving shape
     * @param mx its x at the start (px)
     * @param my its y at the start (px)
     * @param mc cos of its angle
     * @param ms sin of its angle
     * @param dx the translation's x (px)
     * @param dy the translation's y (px)
     * @param x1 the segment's start x (px)
     * @param y1 the segment's start y (px)
     * @param x2 the segment's end x (px)
     * @param y2 the segment's end y (px)
     * @return whether the moving shape touches the segment during the sweep
     */
    public boolean castSegment(Shape moving, float mx, float my, float mc, float ms, float dx, float dy,
            float x1, float y1, float x2, float y2) {
        begin(x1, y1, dx, dy);
        float ex = x2 - x1;
        float ey = y2 - y1;
        float len = EMath.sqrt(ex * ex + ey * ey);
        bvx[0] = 0f;
        bvy[0] = 0f;
        br = 0f;
        if (len > 0f) {
            bn = 2;
            bvx[1] = ex;
            bvy[1] = ey;
            bnx[0] = ey / len;
            bny[0] = -ex / len;
            bnx[1] = -bnx[0];
            bny[1] = -bny[0];
        } else {
            bn = 1;
        }
        grow(Math.abs(ex) + Math.abs(ey));
        castMoving(moving, mx, my, mc, ms);
        return finish();
    }

    private void begin(float originX, float originY, float tx, float ty) {
        ox = originX;
        oy = originY;
        dx = tx;
        dy = ty;
        scale = Math.abs(tx) + Math.abs(ty);
        bestT = Float.POSITIVE_INFINITY;
        bestOverlap = false;
        part = 0;
    }

    private boolean finish() {
        if (!(bestT <= 1f)) {
            return false;
        }
        t = bestT;
        x = ox + bestX;
        y = oy + bestY;
        normalX = bestNx;
        normalY = bestNy;
        overlapping = bestOverlap;
        return true;
    }

    private void grow(float size) {
        if (size > scale) {
            scale = size;
        }
    }

    /** The fixed part (a circle or a polygon) at its pose, relative to the origin. */
    private void loadFixed(Shape p, float px, float py, float c, float s) {
        float rx = px - ox;
        float ry = py - oy;
        if (p.getType() == Shape.TYPE_CIRCLE) {
            Circle circle = (Circle) p;
            bn = 1;
            bvx[0] = rx + c * circle.getCenterX() - s * circle.getCenterY();
            bvy[0] = ry + s * circle.getCenterX() + c * circle.getCenterY();
            br = circle.getRadius();
            grow(Math.abs(bvx[0]) + Math.abs(bvy[0]) + br);
            return;
        }
        Polygon poly = (Polygon) p;
        bn = poly.getVertexCount();
        br = 0f;
        for (int i = 0; i < bn; i++) {
            float lx = poly.getVertexX(i);
            float ly = poly.getVertexY(i);
            bvx[i] = rx + c * lx - s * ly;
            bvy[i] = ry + s * lx + c * ly;
            bnx[i] = c * poly.getNormalX(i) - s * poly.getNormalY(i);
            bny[i] = s * poly.getNormalX(i) + c * poly.getNormalY(i);
            grow(Math.abs(bvx[i]) + Math.abs(bvy[i]));
        }
    }

    /** Casts each part of the moving shape against the loaded fixed part. */
    private void castMoving(Shape moving, float mx, float my, float mc, float ms) {
        if (moving.getType() != Shape.TYPE_MULTI) {
            castPart(moving, mx, my, mc, ms);
            return;
        }
        MultiShape m = (MultiShape) moving;
        for (int i = 0, n = m.getShapeCount(); i < n; i++) {
            castPart(m.getShape(i), mx, my, mc, ms);
        }
    }

    private void castPart(Shape p, float mx, float my, float c, float s) {
        float rx = mx - ox;
        float ry = my - oy;
        if (p.getType() == Shape.TYPE_CIRCLE) {
            Circle circle = (Circle) p;
            an = 1;
            avx[0] = rx + c * circle.getCenterX() - s * circle.getCenterY();
            avy[0] = ry + s * circle.getCenterX() + c * circle.getCenterY();
            ar = circle.getRadius();
            grow(Math.abs(avx[0]) + Math.abs(avy[0]) + ar);
        } else {
            Polygon poly = (Polygon) p;
            an = poly.getVertexCount();
            ar = 0f;
            for (int i = 0; i < an; i++) {
                float lx = poly.getVertexX(i);
                float ly = poly.getVertexY(i);
                avx[i] = rx + c * lx - s * ly;
                avy[i] = ry + s * lx + c * ly;
                anx[i] = c * poly.getNormalX(i) - s * poly.getNormalY(i);
                any[i] = s * poly.getNormalX(i) + c * poly.getNormalY(i);
                grow(Math.abs(avx[i]) + Math.abs(avy[i]));
            }
        }
        if (separation() <= 0f) {
            if (0f < bestT) {
                bestT = 0f;
                bestOverlap = true;
                bestNx = axisX;
                bestNy = axisY;
                // The moving part's deepest point along the way out.
                float px = avx[0] - ar * axisX;
                float py = avy[0] - ar * axisY;
                float low = avx[0] * axisX + avy[0] * axisY;
                for (int i = 1; i < an; i++) {
                    float d = avx[i] * axisX + avy[i] * axisY;
                    if (d < low) {
                        low = d;
                        px = avx[i];
                        py = avy[i];
                    }
                }
                bestX = px;
                bestY = py;
            }
            return;
        }
        if (an == 1) {
            // A circle: its centre against the fixed part grown by its radius.
            if (rounded(avx[0], avy[0], dx, dy, bvx, bvy, bnx, bny, bn, ar + br)) {
                // The contact on the fixed part's surface: its core point, grown by its radius.
                bestX = candX + br * candNx;
                bestY = candY + br * candNy;
                bestNx = candNx;
                bestNy = candNy;
            }
        } else if (bn == 1 && br > 0f) {
            // A fixed circle: its centre against the moving polygon, moving the other way.
            if (rounded(bvx[0], bvy[0], -dx, -dy, avx, avy, anx, any, an, br)) {
                // The point of the circle facing the polygon; the normal out of the circle.
                bestX = bvx[0] - br * candNx;
                bestY = bvy[0] - br * candNy;
                bestNx = -candNx;
                bestNy = -candNy;
            }
        } else {
            // Polygon against polygon or segment: vertices of each against the faces of the other.
            for (int i = 0; i < an; i++) {
                if (rounded(avx[i], avy[i], dx, dy, bvx, bvy, bnx, bny, bn, 0f)) {
                    bestX = candX;
                    bestY = candY;
                    bestNx = candNx;
                    bestNy = candNy;
                }
            }
            for (int j = 0; j < bn; j++) {
                if (rounded(bvx[j], bvy[j], -dx, -dy, avx, avy, anx, any, an, 0f)) {
                    bestX = bvx[j];
                    bestY = bvy[j];
                    bestNx = -candNx;
                    bestNy = -candNy;
                }
            }
        }
    }

    /**
     * The earliest t (before the best so far) at which the point p + t·d meets the convex core
     * (n vertices: a point, a segment or a polygon) grown by radius r: through a face pushed out by
     * r, or, when r &gt; 0, a disc of radius r round a vertex. Sets bestT and the candidate's
     * outward normal and contact point on the core.
     */
    private boolean rounded(float px, float py, float tx, float ty, float[] vx, float[] vy, float[] nx, float[] ny,
            int n, float r) {
        boolean found = false;
        if (n >= 2) {
            for (int i = 0; i < n; i++) {
                float den = nx[i] * tx + ny[i] * ty;
                if (!(den < 0f)) {
                    continue;
                }
                float s = nx[i] * (px - vx[i]) + ny[i] * (py - vy[i]) - r;
                if (s < 0f) {
                    continue;
                }
                float u = s / -den;
                if (!(u < bestT) || u > 1f) {
                    continue;
                }
                // Where the grown face is met, back on the core's face.
                float qx = px + u * tx - r * nx[i];
                float qy = py + u * ty - r * ny[i];
                int k = i + 1 == n ? 0 : i + 1;
                float ex = vx[k] - vx[i];
                float ey = vy[k] - vy[i];
                float len2 = ex * ex + ey * ey;
                float along = (qx - vx[i]) * ex + (qy - vy[i]) * ey;
                // Corners of a grown core are its discs; bare corners need the stretch.
                float slack = r > 0f ? 0f : (STRETCH + ROUNDING * scale / EMath.sqrt(len2)) * len2;
                if (along < -slack || along > len2 + slack) {
                    continue;
                }
                bestT = u;
                bestOverlap = false;
                candNx = nx[i];
                candNy = ny[i];
                candX = qx;
                candY = qy;
                found = true;
            }
        }
        if (r > 0f) {
            float a = tx * tx + ty * ty;
            for (int i = 0; i < n; i++) {
                float fx = px - vx[i];
                float fy = py - vy[i];
                float b = fx * tx + fy * ty;
                if (!(b < 0f)) {
                    continue;
                }
                float c = fx * fx + fy * fy - r * r;
                float disc = b * b - a * c;
                if (c < 0f || disc < 0f) {
                    continue;
                }
                // The smaller root c / (−b + √disc), free of cancellation.
                float u = c / (EMath.sqrt(disc) - b);
                if (!(u < bestT) || u > 1f) {
                    continue;
                }
                float hx = fx + u * tx;
                float hy = fy + u * ty;
                float len = EMath.sqrt(hx * hx + hy * hy);
                if (!(len > 0f)) {
                    continue;
                }
                bestT = u;
                bestOverlap = false;
                candNx = hx / len;
                candNy = hy / len;
                candX = vx[i];
                candY = vy[i];
                found = true;
            }
        }
        return found;
    }

    /**
     * The largest separation of the loaded parts over the axes that decide whether two convex
     * parts overlap (the faces of both, and for a circle the axis to the other part's nearest
     * vertex or centre): positive when they are apart, ≤ 0 when they overlap or touch; the axis,
     * pointing from the fixed part to the moving one, in axisX, axisY.
     */
    private float separation() {
        float best = Float.NEGATIVE_INFINITY;
        axisX = 0f;
        axisY = -1f;
        // The fixed part's faces.
        if (bn >= 2) {
            for (int j = 0; j < bn; j++) {
                float ux = bnx[j];
                float uy = bny[j];
                float g = lowA(ux, uy) - (ux * bvx[j] + uy * bvy[j]);
                if (g > best) {
                    best = g;
                    axisX = ux;
                    axisY = uy;
                }
            }
        }
        // The moving part's faces, turned to point from the fixed part to it.
        if (an >= 2) {
            for (int i = 0; i < an; i++) {
                float ux = -anx[i];
                float uy = -any[i];
                float g = (ux * avx[i] + uy * avy[i]) - highB(ux, uy);
                if (g > best) {
                    best = g;
                    axisX = ux;
                    axisY = uy;
                }
            }
        }
        // A circle on either side: the axis between its centre and the other part's nearest vertex.
        if (an == 1 || bn == 1) {
            float[] cx = an == 1 ? avx : bvx;
            float[] cy = an == 1 ? avy : bvy;
            float[] ox2 = an == 1 ? bvx : avx;
            float[] oy2 = an == 1 ? bvy : avy;
            int on = an == 1 ? bn : an;
            int nearest = 0;
            float nearestD = Float.POSITIVE_INFINITY;
            for (int i = 0; i < on; i++) {
                float ex = cx[0] - ox2[i];
                float ey = cy[0] - oy2[i];
                float d = ex * ex + ey * ey;
                if (d < nearestD) {
                    nearestD = d;
                    nearest = i;
                }
            }
            // From the fixed side to the moving side.
            float ux = an == 1 ? avx[0] - bvx[nearest] : avx[nearest] - bvx[0];
            float uy = an == 1 ? avy[0] - bvy[nearest] : avy[nearest] - bvy[0];
            float len = EMath.sqrt(ux * ux + uy * uy);
            if (len > 0f) {
                ux /= len;
                uy /= len;
                float g = lowA(ux, uy) - highB(ux, uy);
                if (g > best) {
                    best = g;
                    axisX = ux;
                    axisY = uy;
                }
            } else if (best == Float.NEGATIVE_INFINITY) {
                best = -(ar + br);
            }
        }
        return best;
    }

    /** The lowest projection of the moving part on a unit axis. */
    private float lowA(float ux, float uy) {
        float low = Float.POSITIVE_INFINITY;
        for (int i = 0; i < an; i++) {
            low = Math.min(low, ux * avx[i] + uy * avy[i]);
        }
        return low - ar;
    }

    /** The highest projection of the fixed part on a unit axis. */
    private float highB(float ux, float uy) {
        float high = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < bn; i++) {
            high = Math.max(high, ux * bvx[i] + uy * bvy[i]);
        }
        return high + br;
    }
}
