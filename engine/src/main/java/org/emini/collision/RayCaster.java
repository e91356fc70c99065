package org.emini.collision;

import org.emini.math.EMath;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * A ray, the segment a → b parametrised as a + t·(b − a) for t in [0, 1], against a circle, a
 * convex polygon, a multi-shape or a line segment, and point containment: the geometry shared by
 * the world's ray casts ({@code Simulation.rayCast}) and the particles' bounces.
 *
 * <p>Shapes are tested in their own local frame: transform the ray's ends into it first (a hit's
 * parameter t does not change under that affine map). Shapes are closed: a ray that touches one
 * (a tangent to a circle, a ray grazing a polygon's corner or running along its edge) hits it. A
 * ray that starts inside or on a shape hits it at t = 0, and the hit then gives the shortest way
 * out: the point on the nearest face of a polygon, or radially out of a circle (straight up, (0,
 * −1), from its exact centre). A zero-length ray (a = b) is thus a point test. A line segment has
 * no inside: it is hit from either side by a ray that crosses or touches it, not by one that starts
 * on its line or runs along it.
 *
 * <p>The result of the last successful test is in the public fields: {@link #t}, the point
 * ({@link #x}, {@link #y}) on the surface, the outward unit normal there ({@link #normalX},
 * {@link #normalY}) and, for a multi-shape, the {@link #part} hit. The point is put on the surface
 * exactly (on a polygon's face line, at the radius, on the segment's line) and then {@link #getSkin()
 * the skin} outwards along the normal; a segment is also stretched by the skin at both ends. The
 * world's queries use no skin; the particles use 1/128 px so that a bounced particle is outside
 * whatever the rounding, and so that a path through the joint of two segments is caught.
 *
 * <p>Plain float arithmetic, no allocation; not thread-safe (one instance per user).
 */
public final class RayCaster {
    private final float skin;

    /** The ray parameter of the last hit, in [0, 1]. */
    public float t;
    /** The x of the last hit's point, in the frame of the shape tested (px). */
    public float x;
    /** The y of the last hit's point (px). */
    public float y;
    /** The x of the unit normal at the last hit, out of the shape (towards the ray's start for a segment). */
    public float normalX;
    /** The y of the unit normal at the last hit. */
    public float normalY;
    /** The part of a multi-shape hit (or containing the point) by the last test; 0 for other shapes. */
    public int part;

    /**
     * Creates a ray caster.
     *
     * @param skin how far outside the surface a hit's point is put, and by how much segments are
     *     stretched at both ends (px), finite and &ge; 0: 0 for exact hits
     * @throws IllegalArgumentException if the skin is negative, NaN or infinite
     */
    public RayCaster(float skin) {
        if (!EMath.isFinite(skin) || skin < 0f) {
            throw new IllegalArgumentException("RayCaster: skin must be a finite number >= 0, was " + skin);
        }
        this.skin = skin;
    }

    /**
     * The distance by which hit points are put outside the surface.
     *
     * @return the skin (px)
     */
    public float getSkin() {
        return skin;
    }

    /**
     * Casts the ray against a shape of any kind; for a multi-shape the earliest hit among its
     * parts (the first part on a tie), with its index in {@link #part}.
     *
     * @param shape the shape
     * @param ax the ray's start x, in the shape's frame (px)
     * @param ay the ray's start y (px)
     * @param bx the ray's end x (px)
     * @param by the ray's end y (px)
     * @return whether the ray hits the shape; the fields hold the hit when it does
     */
    public boolean shape(Shape shape, float ax, float ay, float bx, float by) {
        int type = shape.getType();
        part = 0;
        if (type == Shape.TYPE_CIRCLE) {
            return circle((Circle) shape, ax, ay, bx, by);
        }
        if (type == Shape.TYPE_POLYGON) {
            return polygon((Polygon) shape, ax, ay, bx, by);
        }
        MultiShape multi = (MultiShape) shape;
        float bestT = Float.POSITIVE_INFINITY;
        float hx = 0f;
        float hy = 0f;
        float nx = 0f;
        float ny = 0f;
        int bestPart = 0;
        for (int i = 0, n = multi.getShapeCount(); i < n; i++) {
            Shape p = multi.getShape(i);
            boolean hit = p.getType() == Shape.TYPE_CIRCLE ? circle((Circle) p, ax, ay, bx, by)
                : polygon((Polygon) p, ax, ay, bx, by);
            if (hit && t < bestT) {
                bestT = t;
                hx = x;
                hy = y;
                nx = normalX;
                ny = normalY;
                bestPart = i;
            }
        }
        t = bestT;
        x = hx;
        y = hy;
        normalX = nx;
        normalY = ny;
        part = bestPart;
        return bestT <= 1f;
    }

    /**
     * Casts the ray against a circle: the smaller root of |a + t(b − a) − c|² = r². A start inside
     * or on the rim is a hit at t = 0, out along the radius.
     *
     * @param circle the circle
     * @param ax the ray's start x, in the circle's frame (px)
     * @param ay the ray's start y (px)
     * @param bx the ray's end x (px)
     * @param by the ray's end y (px)
     * @return whether the ray hits the circle
     */
    public boolean circle(Circle circle, float ax, float ay, float bx, float by) {
        float cx = circle.getCenterX();
        float cy = circle.getCenterY();
        float r = circle.getRadius();
        float fx = ax - cx;
        float fy = ay - cy;
        float c = fx * fx + fy * fy - r * r;
        if (c <= 0f) {
            t = 0f;
            radial(circle, fx, fy);
            return true;
        }
        float dx = bx - ax;
        float dy = by - ay;
        float half = fx * dx + fy * dy;
        if (half >= 0f) {
            return false;
        }
        float aa = dx * dx + dy * dy;
        float disc = half * half - aa * c;
        if (disc < 0f) {
            return false;
        }
        float root = (-half - EMath.sqrt(disc)) / aa;
        if (root > 1f) {
            return false;
        }
        t = Math.max(0f, root);
        radial(circle, fx + t * dx, fy + t * dy);
        return true;
    }

    /**
     * Casts the ray against a convex polygon by clipping it to the face half-planes (Cyrus–Beck):
     * it enters at the largest entering parameter, through that face, if that is not after it
     * leaves. A start inside or on the boundary is a hit at t = 0 through the face nearest to it.
     *
     * @param p the polygon
     * @param ax the ray's start x, in the polygon's frame (px)
     * @param ay the ray's start y (px)
     * @param bx the ray's end x (px)
     * @param by the ray's end y (px)
     * @return whether the ray hits the polygon
     */
    public boolean polygon(Polygon p, float ax, float ay, float bx, float by) {
        int face = -1;
        float enter = 0f;
        float leave = 1f;
        int nearest = 0;
        float nearestDepth = Float.NEGATIVE_INFINITY;
        for (int i = 0, n = p.getVertexCount(); i < n; i++) {
            float nx = p.getNormalX(i);
            float ny = p.getNormalY(i);
            float d = nx * p.getVertexX(i) + ny * p.getVertexY(i);
            float da = nx * ax + ny * ay - d;
            float db = nx * bx + ny * by - d;
            if (da > 0f) {
                if (db > 0f) {
                    return false;
                }
                float u = da / (da - db);
                if (face < 0 || u > enter) {
                    enter = u;
                    face = i;
                }
            } else {
                if (da > nearestDepth) {
                    nearestDepth = da;
                    nearest = i;
                }
                if (db > 0f) {
                    float u = da / (da - db);
                    if (u < leave) {
                        leave = u;
                    }
                }
            }
        }
        float qx = ax;
        float qy = ay;
        if (face < 0) {
            face = nearest;
            t = 0f;
        } else {
            if (enter > leave) {
                return false;
            }
            t = enter;
            qx += enter * (bx - ax);
            qy += enter * (by - ay);
        }
        surface(p, face, qx, qy);
        return true;
    }

    /**
     * Crosses the ray with the segment (x1, y1) → (x2, y2), from either side, the segment
     * stretched by the skin at both ends. A ray starting on the segment's line, or running along
     * it, does not cross it; a zero-length segment is never hit. The normal points to the ray's
     * start side.
     *
     * @param x1 the segment's start x (px)
     * @param y1 the segment's start y (px)
     * @param x2 the segment's end x (px)
     * @param y2 the segment's end y (px)
     * @param ax the ray's start x (px)
     * @param ay the ray's start y (px)
     * @param bx the ray's end x (px)
     * @param by the ray's end y (px)
     * @return whether the ray crosses the segment
     */
    public boolean segment(float x1, float y1, float x2, float y2, float ax, float ay, float bx, float by) {
        float px = x1;
        float py = y1;
        float ex = x2 - px;
        float ey = y2 - py;
        // Twice the signed areas: the sides of a and b, scaled by the segment's length.
        float da = ex * (ay - py) - ey * (ax - px);
        float db = ex * (by - py) - ey * (bx - px);
        if (da == 0f || da > 0f && db > 0f || da < 0f && db < 0f) {
            return false;
        }
        float len2 = ex * ex + ey * ey;
        if (!(len2 > 0f)) {
            return false;
        }
        float u = da / (da - db);
        float qx = ax + u * (bx - ax);
        float qy = ay + u * (by - ay);
        float len = EMath.sqrt(len2);
        float along = ((qx - px) * ex + (qy - py) * ey) / len;
        if (along < -skin || along > len + skin) {
            return false;
        }
        // The normal on a's side; the hit on the line, then the skin out.
        float nx = -ey / len;
        float ny = ex / len;
        if (da < 0f) {
            nx = -nx;
            ny = -ny;
        }
        float out = skin - (nx * (qx - px) + ny * (qy - py));
        t = u;
        x = qx + out * nx;
        y = qy + out * ny;
        normalX = nx;
        normalY = ny;
        part = 0;
        return true;
    }

    /**
     * Whether a point is inside or on a shape (for a multi-shape: in one of its parts, the first
     * such in {@link #part}); if so, the fields give the shortest way out as a hit at t = 0.
     *
     * @param shape the shape
     * @param px the point's x, in the shape's frame (px)
     * @param py the point's y (px)
     * @return whether the shape contains the point
     */
    public boolean contains(Shape shape, float px, float py) {
        int type = shape.getType();
        part = 0;
        if (type == Shape.TYPE_CIRCLE) {
            return containsCircle((Circle) shape, px, py);
        }
        if (type == Shape.TYPE_POLYGON) {
            return containsPolygon((Polygon) shape, px, py);
        }
        MultiShape multi = (MultiShape) shape;
        for (int i = 0, n = multi.getShapeCount(); i < n; i++) {
            Shape p = multi.getShape(i);
            boolean in = p.getType() == Shape.TYPE_CIRCLE ? containsCircle((Circle) p, px, py)
                : containsPolygon((Polygon) p, px, py);
            if (in) {
                part = i;
                return true;
            }
        }
        return false;
    }

    /**
     * Whether a point is inside or on a polygon; if so, the fields give the way out through the
     * nearest face.
     *
     * @param p the polygon
     * @param px the point's x, in the polygon's frame (px)
     * @param py the point's y (px)
     * @return whether the polygon contains the point
     */
    public boolean containsPolygon(Polygon p, float px, float py) {
        int nearest = 0;
        float nearestDepth = Float.NEGATIVE_INFINITY;
        for (int i = 0, n = p.getVertexCount(); i < n; i++) {
            float nx = p.getNormalX(i);
            float ny = p.getNormalY(i);
            float depth = nx * (px - p.getVertexX(i)) + ny * (py - p.getVertexY(i));
            if (depth > 0f) {
                return false;
            }
            if (depth > nearestDepth) {
                nearestDepth = depth;
                nearest = i;
            }
        }
        t = 0f;
        surface(p, nearest, px, py);
        return true;
    }

    /**
     * Whether a point is inside or on a circle; if so, the fields give the way out along the
     * radius.
     *
     * @param circle the circle
     * @param px the point's x, in the circle's frame (px)
     * @param py the point's y (px)
     * @return whether the circle contains the point
     */
    public boolean containsCircle(Circle circle, float px, float py) {
        float fx = px - circle.getCenterX();
        float fy = py - circle.getCenterY();
        float r = circle.getRadius();
        if (fx * fx + fy * fy > r * r) {
            return false;
        }
        t = 0f;
        radial(circle, fx, fy);
        return true;
    }

    /** Puts the hit on a face's line exactly, then the skin outside it, whatever the rounding so far. */
    private void surface(Polygon p, int face, float qx, float qy) {
        float nx = p.getNormalX(face);
        float ny = p.getNormalY(face);
        float out = skin - (nx * (qx - p.getVertexX(face)) + ny * (qy - p.getVertexY(face)));
        x = qx + out * nx;
        y = qy + out * ny;
        normalX = nx;
        normalY = ny;
    }

    /** Puts the hit the skin outside the rim along the direction (qx, qy) from the centre. */
    private void radial(Circle circle, float qx, float qy) {
        float len = EMath.sqrt(qx * qx + qy * qy);
        float nx = 0f;
        float ny = -1f;
        if (len > 0f) {
            nx = qx / len;
            ny = qy / len;
        }
        float r = circle.getRadius() + skin;
        x = circle.getCenterX() + nx * r;
        y = circle.getCenterY() + ny * r;
        normalX = nx;
        normalY = ny;
    }
}
