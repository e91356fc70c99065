package org.emini.collision;

import org.emini.math.EMath;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * Time of impact of a moving shape against a fixed one, by conservative advancement.
 *
 * <p>The moving shape follows the straight sweep from pose 0 to pose 1 (position and angle
 * interpolated linearly). At each iterate a lower bound of the distance between the shapes is
 * divided by an upper bound of how fast any point of the moving shape can approach (its
 * displacement plus its rotation times its bounding radius), which gives a step that cannot skip
 * a contact. The loop stops once the shapes are within the target distance or the sweep ends.
 * Because the step only uses a lower bound, the returned time is always safe: at that time the
 * shapes do not overlap. Works for spinning bodies with long arms, which a one-step look-ahead
 * (the original engine's approach) misses.
 *
 * <p>One instance per world; no allocation; not thread-safe.
 */
public final class TimeOfImpact {
    /** Iteration cap; reaching it returns the last safe time. */
    public static final int MAX_ITERATIONS = 40;

    private int lastIterations;
    // What the current sweep is against: a placed shape, or a segment.
    private Shape fixedShape;
    private Segment fixedSegment;
    private float fx;
    private float fy;
    private float fc;
    private float fs;

    /** Creates a solver. */
    public TimeOfImpact() {
    }

    /**
     * Iterations used by the last call, for diagnostics.
     *
     * @return the iteration count
     */
    public int getLastIterations() {
        return lastIterations;
    }

    /**
     * The first time in [0, 1] at which a moving shape comes within {@code target} of a fixed one.
     *
     * @param moving the moving shape
     * @param x0 start x of its origin (px)
     * @param y0 start y (px)
     * @param angle0 start angle (rad)
     * @param x1 end x (px)
     * @param y1 end y (px)
     * @param angle1 end angle (rad)
     * @param fixed the fixed shape
     * @param fx its x (px)
     * @param fy its y (px)
     * @param fc cos of its angle
     * @param fs sin of its angle
     * @param target the distance at which the sweep stops (px), &gt; 0
     * @return the time of impact in [0, 1], or 1 when the sweep ends without impact
     */
    public float solve(Shape moving, float x0, float y0, float angle0, float x1, float y1, float angle1,
            Shape fixed, float fx, float fy, float fc, float fs, float target) {
        fixedShape = fixed;
        fixedSegment = null;
        this.fx = fx;
        this.fy = fy;
        this.fc = fc;
        this.fs = fs;
        return advance(moving, x0, y0, angle0, x1, y1, angle1, target);
    }

    /**
     * The first time in [0, 1] at which a moving shape comes within {@code target} of a landscape
     * segment, which is solid from both sides here (the caller decides whether a faced segment
     * stops the shape at all).
     *
     * @param moving the moving shape
     * @param x0 start x of its origin (px)
     * @param y0 start y (px)
     * @param angle0 start angle (rad)
     * @param x1 end x (px)
     * @param y1 end y (px)
     * @param angle1 end angle (rad)
     * @param segment the segment
     * @param target the distance at which the sweep stops (px), &gt; 0
     * @return the time of impact in [0, 1], or 1 when the sweep ends without impact
     */
    public float solveSegment(Shape moving, float x0, float y0, float angle0, float x1, float y1, float angle1,
            Segment segment, float target) {
        fixedShape = null;
        fixedSegment = segment;
        return advance(moving, x0, y0, angle0, x1, y1, angle1, target);
    }

    private float distance(Shape moving, float x, float y, float c, float s) {
        return fixedSegment != null ? segmentSeparation(moving, x, y, c, s, fixedSegment)
            : separation(moving, x, y, c, s, fixedShape, fx, fy, fc, fs);
    }

    private float advance(Shape moving, float x0, float y0, float angle0, float x1, float y1, float angle1,
            float target) {
        float dx = x1 - x0;
        float dy = y1 - y0;
        float da = angle1 - angle0;
        float bound = EMath.sqrt(dx * dx + dy * dy) + Math.abs(da) * moving.getBoundingRadius();
        float t = 0f;
        lastIterations = 0;
        if (bound <= 0f) {
            return 1f;
        }
        float d0 = distance(moving, x0, y0, EMath.cos(angle0), EMath.sin(angle0));
        // Apart: stop within the target distance. Already touching (the contact solver owns the
        // pair): stop only where the body would sink deeper than it started by more than the
        // target, which catches a fast body rotating into what it touches.
        float stopAt = d0 > target ? 0.5f * target : Math.min(d0, 0f) - target;
        float tolerance = 0.5f * target;
        while (lastIterations < MAX_ITERATIONS) {
            lastIterations++;
            float a = angle0 + t * da;
            float d = distance(moving, x0 + t * dx, y0 + t * dy, EMath.cos(a), EMath.sin(a));
            if (d <= stopAt + tolerance) {
                return t;
            }
            // The distance falls no faster than the bound: this step cannot skip the stop.
            t += (d - stopAt) / bound;
            if (t >= 1f) {
                return 1f;
            }
        }
        return t;
    }

    /**
     * The radius of the shape's core: a quarter of the distance from its origin to its nearest
     * boundary. Used to keep a body's centre from passing through walls it already touches.
     *
     * @param shape the shape
     * @return the core radius (px), 0 when the origin is outside the shape
     */
    public static float coreRadius(Shape shape) {
        if (shape.getType() == Shape.TYPE_CIRCLE) {
            Circle c = (Circle) shape;
            float off = EMath.sqrt(c.getCenterX() * c.getCenterX() + c.getCenterY() * c.getCenterY());
            return Math.max(0.25f * (c.getRadius() - off), 0f);
        }
        if (shape.getType() == Shape.TYPE_POLYGON) {
            Polygon p = (Polygon) shape;
            float min = Float.MAX_VALUE;
            for (int i = 0; i < p.getVertexCount(); i++) {
                min = Math.min(min, p.getNormalX(i) * p.getVertexX(i) + p.getNormalY(i) * p.getVertexY(i));
            }
            return Math.max(0.25f * min, 0f);
        }
        if (shape.getType() == Shape.TYPE_MULTI) {
            // The origin is at least as deep in the union as in the part that holds it deepest.
            MultiShape m = (MultiShape) shape;
            float best = 0f;
            for (int i = 0; i < m.getShapeCount(); i++) {
                best = Math.max(best, coreRadius(m.getShape(i)));
            }
            return best;
        }
        return 0f;
    }

    /**
     * A lower bound of the distance between two placed shapes: positive when they are apart,
     * zero or negative when they may touch. Separating-axis projections never exceed the true
     * distance, so any set of axes gives a valid bound.
     *
     * @param a shape A
     * @param ax its x (px)
     * @param ay its y (px)
     * @param ac cos of its angle
     * @param as sin of its angle
     * @param b shape B
     * @param bx its x (px)
     * @param by its y (px)
     * @param bc cos of its angle
     * @param bs sin of its angle
     * @return the bound (px)
     */
    public static float separation(Shape a, float ax, float ay, float ac, float as,
            Shape b, float bx, float by, float bc, float bs) {
        int ta = a.getType();
        int tb = b.getType();
        if (ta == Shape.TYPE_MULTI || tb == Shape.TYPE_MULTI) {
            // The nearest pair of parts: the smallest of lower bounds bounds the smallest distance.
            boolean splitA = ta == Shape.TYPE_MULTI;
            MultiShape m = (MultiShape) (splitA ? a : b);
            float best = Float.MAX_VALUE;
            for (int i = 0; i < m.getShapeCount(); i++) {
                float d = splitA ? separation(m.getShape(i), ax, ay, ac, as, b, bx, by, bc, bs)
                    : separation(a, ax, ay, ac, as, m.getShape(i), bx, by, bc, bs);
                best = Math.min(best, d);
            }
            return best;
        }
        if (ta == Shape.TYPE_POLYGON && tb == Shape.TYPE_POLYGON) {
            Polygon pa = (Polygon) a;
            Polygon pb = (Polygon) b;
            return Math.max(faceSeparation(pa, ax, ay, ac, as, pb, bx, by, bc, bs),
                faceSeparation(pb, bx, by, bc, bs, pa, ax, ay, ac, as));
        }
        if (ta == Shape.TYPE_CIRCLE && tb == Shape.TYPE_CIRCLE) {
            Circle ca = (Circle) a;
            Circle cb = (Circle) b;
            float px = ax + ac * ca.getCenterX() - as * ca.getCenterY();
            float py = ay + as * ca.getCenterX() + ac * ca.getCenterY();
            float qx = bx + bc * cb.getCenterX() - bs * cb.getCenterY();
            float qy = by + bs * cb.getCenterX() + bc * cb.getCenterY();
            float ex = qx - px;
            float ey = qy - py;
            return EMath.sqrt(ex * ex + ey * ey) - ca.getRadius() - cb.getRadius();
        }
        if (ta == Shape.TYPE_POLYGON && tb == Shape.TYPE_CIRCLE) {
            Circle c = (Circle) b;
            return polygonCircle((Polygon) a, ax, ay, ac, as, bx + bc * c.getCenterX() - bs * c.getCenterY(),
                by + bs * c.getCenterX() + bc * c.getCenterY(), c.getRadius());
        }
        if (ta == Shape.TYPE_CIRCLE && tb == Shape.TYPE_POLYGON) {
            Circle c = (Circle) a;
            return polygonCircle((Polygon) b, bx, by, bc, bs, ax + ac * c.getCenterX() - as * c.getCenterY(),
                ay + as * c.getCenterX() + ac * c.getCenterY(), c.getRadius());
        }
        throw new IllegalArgumentException("TimeOfImpact.separation: no bound for shape types " + ta + " and " + tb);
    }

    /**
     * A lower bound of the distance between a placed shape and a segment (solid from both sides):
     * the exact distance for a circle, separating axes (the segment's normal, the polygon's faces)
     * for a polygon, the nearest part for a multi-shape.
     *
     * @param a the shape
     * @param ax its x (px)
     * @param ay its y (px)
     * @param ac cos of its angle
     * @param as sin of its angle
     * @param seg the segment
     * @return the bound (px)
     */
    public static float segmentSeparation(Shape a, float ax, float ay, float ac, float as, Segment seg) {
        int type = a.getType();
        if (type == Shape.TYPE_MULTI) {
            MultiShape m = (MultiShape) a;
            float best = Float.MAX_VALUE;
            for (int i = 0; i < m.getShapeCount(); i++) {
                best = Math.min(best, segmentSeparation(m.getShape(i), ax, ay, ac, as, seg));
            }
            return best;
        }
        float ex = seg.x2 - seg.x1;
        float ey = seg.y2 - seg.y1;
        float len2 = ex * ex + ey * ey;
        if (type == Shape.TYPE_CIRCLE) {
            Circle c = (Circle) a;
            float px = ax + ac * c.getCenterX() - as * c.getCenterY() - seg.x1;
            float py = ay + as * c.getCenterX() + ac * c.getCenterY() - seg.y1;
            float t = len2 > 0f ? (px * ex + py * ey) / len2 : 0f;
            t = t < 0f ? 0f : (t > 1f ? 1f : t);
            float qx = px - t * ex;
            float qy = py - t * ey;
            return EMath.sqrt(qx * qx + qy * qy) - c.getRadius();
        }
        Polygon p = (Polygon) a;
        int n = p.getVertexCount();
        float best = -Float.MAX_VALUE;
        float len = EMath.sqrt(len2);
        if (len > 0f) {
            // The segment's normal, both ways: the polygon wholly on one side.
            float nx = -ey / len;
            float ny = ex / len;
            float low = Float.MAX_VALUE;
            float high = -Float.MAX_VALUE;
            for (int j = 0; j < n; j++) {
                float lx = p.getVertexX(j);
                float ly = p.getVertexY(j);
                float d = (ax + ac * lx - as * ly - seg.x1) * nx + (ay + as * lx + ac * ly - seg.y1) * ny;
                low = Math.min(low, d);
                high = Math.max(high, d);
            }
            best = Math.max(low, -high);
        }
        for (int i = 0; i < n; i++) {
            float lnx = p.getNormalX(i);
            float lny = p.getNormalY(i);
            float nx = ac * lnx - as * lny;
            float ny = as * lnx + ac * lny;
            float lvx = p.getVertexX(i);
            float lvy = p.getVertexY(i);
            float vx = ax + ac * lvx - as * lvy;
            float vy = ay + as * lvx + ac * lvy;
            float d = Math.min((seg.x1 - vx) * nx + (seg.y1 - vy) * ny, (seg.x2 - vx) * nx + (seg.y2 - vy) * ny);
            best = Math.max(best, d);
        }
        return best;
    }

    /** Largest separation of B from A along A's face normals. */
    private static float faceSeparation(Polygon a, float ax, float ay, float ac, float as,
            Polygon b, float bx, float by, float bc, float bs) {
        float best = -Float.MAX_VALUE;
        int na = a.getVertexCount();
        int nb = b.getVertexCount();
        for (int i = 0; i < na; i++) {
            float lnx = a.getNormalX(i);
            float lny = a.getNormalY(i);
            float nx = ac * lnx - as * lny;
            float ny = as * lnx + ac * lny;
            float lvx = a.getVertexX(i);
            float lvy = a.getVertexY(i);
            float vx = ax + ac * lvx - as * lvy;
            float vy = ay + as * lvx + ac * lvy;
            float min = Float.MAX_VALUE;
            for (int j = 0; j < nb; j++) {
                float lx = b.getVertexX(j);
                float ly = b.getVertexY(j);
                float d = (bx + bc * lx - bs * ly - vx) * nx + (by + bs * lx + bc * ly - vy) * ny;
                if (d < min) {
                    min = d;
                }
            }
            if (min > best) {
                best = min;
            }
        }
        return best;
    }

    /** Lower bound of the distance from a fixed shape to a disc (centre cx, cy, radius r). */
    static float discSeparation(Shape fixed, float fx, float fy, float fc, float fs, float cx, float cy, float r) {
        if (fixed.getType() == Shape.TYPE_POLYGON) {
            return polygonCircle((Polygon) fixed, fx, fy, fc, fs, cx, cy, r);
        }
        if (fixed.getType() == Shape.TYPE_CIRCLE) {
            Circle c = (Circle) fixed;
            float ex = cx - (fx + fc * c.getCenterX() - fs * c.getCenterY());
            float ey = cy - (fy + fs * c.getCenterX() + fc * c.getCenterY());
            return EMath.sqrt(ex * ex + ey * ey) - c.getRadius() - r;
        }
        throw new IllegalArgumentException("TimeOfImpact: no bound for shape type " + fixed.getType());
    }

    private static float polygonCircle(Polygon p, float px, float py, float pc, float ps, float cx, float cy, float r) {
        float best = -Float.MAX_VALUE;
        float nearest = Float.MAX_VALUE;
        float nearestX = 0f;
        float nearestY = 0f;
        int n = p.getVertexCount();
        for (int i = 0; i < n; i++) {
            float lvx = p.getVertexX(i);
            float lvy = p.getVertexY(i);
            float vx = px + pc * lvx - ps * lvy;
            float vy = py + ps * lvx + pc * lvy;
            float lnx = p.getNormalX(i);
            float lny = p.getNormalY(i);
            float d = (cx - vx) * (pc * lnx - ps * lny) + (cy - vy) * (ps * lnx + pc * lny) - r;
            if (d > best) {
                best = d;
            }
            float ex = cx - vx;
            float ey = cy - vy;
            float dd = ex * ex + ey * ey;
            if (dd < nearest) {
                nearest = dd;
                nearestX = vx;
                nearestY = vy;
            }
        }
        // The axis from the nearest vertex to the centre: tight in the vertex regions.
        float len = EMath.sqrt(nearest);
        if (len > 0f) {
            float ux = (cx - nearestX) / len;
            float uy = (cy - nearestY) / len;
            float max = -Float.MAX_VALUE;
            for (int i = 0; i < n; i++) {
                float lvx = p.getVertexX(i);
                float lvy = p.getVertexY(i);
                float proj = (px + pc * lvx - ps * lvy) * ux + (py + ps * lvx + pc * lvy) * uy;
                if (proj > max) {
                    max = proj;
                }
            }
            float d = cx * ux + cy * uy - r - max;
            if (d > best) {
                best = d;
            }
        }
        return best;
    }
}
