package org.emini.collision;

import org.emini.math.EMath;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * Narrowphase collision between two placed shapes. One per world: it owns the scratch buffers, so
 * no call allocates, and it holds no static state. Not thread-safe; use one per thread.
 *
 * <p>Each shape is placed by a position (x, y) of its local origin and a rotation given as
 * c = cos θ and s = sin θ, mapping a local point (lx, ly) to (x + c·lx − s·ly, y + s·lx + c·ly).
 * The result goes to a {@link Manifold} whose normal points from A to B. Points whose separation
 * exceeds the speculative distance are left out; points with a smaller positive gap are reported
 * so the solver can stop the shapes before they touch.
 */
public final class Collider {
    // A circle centre closer to the polygon than this fraction of the polygon's bounding radius is
    // treated as on the face: the direction to a vertex is too unreliable to be a normal.
    private static final float VERTEX_REGION_TOLERANCE = 1e-5f;
    // Circle centres closer than this fraction of the radius sum count as coincident.
    private static final float COINCIDENT_TOLERANCE = 1e-6f;

    private final PolygonCollider polygons = new PolygonCollider();
    private final SegmentCollider segments = new SegmentCollider(polygons);
    private float apartGap = Float.NEGATIVE_INFINITY;

    /** Creates a collider with its scratch buffers. */
    public Collider() {
    }

    /**
     * Collides two shapes of any supported pair of types.
     *
     * @param a shape A
     * @param ax the world x of A's local origin (px)
     * @param ay the world y of A's local origin (px)
     * @param ac cos of A's rotation
     * @param as sin of A's rotation
     * @param b shape B
     * @param bx the world x of B's local origin (px)
     * @param by the world y of B's local origin (px)
     * @param bc cos of B's rotation
     * @param bs sin of B's rotation
     * @param speculativeDistance the largest gap still reported (px), normally &ge; 0
     * @param out receives the contact; pointCount 0 when the shapes are farther apart
     * @throws IllegalArgumentException if the pair of shape types is not supported (a
     *     {@link org.emini.shape.MultiShape} collides part by part: pass its parts)
     */
    public void collide(Shape a, float ax, float ay, float ac, float as, Shape b, float bx,
            float by, float bc, float bs, float speculativeDistance, Manifold out) {
        int ta = a.getType();
        int tb = b.getType();
        if (ta == Shape.TYPE_POLYGON && tb == Shape.TYPE_POLYGON) {
            polygons.collide((Polygon) a, ax, ay, ac, as, (Polygon) b, bx, by, bc, bs,
                    speculativeDistance, out);
            apartGap = polygons.apartGap;
        } else if (ta == Shape.TYPE_POLYGON && tb == Shape.TYPE_CIRCLE) {
            collidePolygonCircle((Polygon) a, ax, ay, ac, as, (Circle) b, bx, by, bc, bs,
                    speculativeDistance, out);
        } else if (ta == Shape.TYPE_CIRCLE && tb == Shape.TYPE_POLYGON) {
            collidePolygonCircle((Polygon) b, bx, by, bc, bs, (Circle) a, ax, ay, ac, as,
                    speculativeDistance, out);
            // Points and separations are symmetric; only the direction depends on the order.
            out.normalX = -out.normalX;
            out.normalY = -out.normalY;
        } else if (ta == Shape.TYPE_CIRCLE && tb == Shape.TYPE_CIRCLE) {
            collideCircles((Circle) a, ax, ay, ac, as, (Circle) b, bx, by, bc, bs,
                    speculativeDistance, out);
        } else {
            throw new IllegalArgumentException("Collider.collide: no narrowphase for shape types "
                    + ta + " and " + tb);
        }
    }

    /**
     * Whether two placed shapes of any kind overlap (touching counts), multi-shapes part by part:
     * the exact overlap test behind sensors.
     *
     * @param a shape A
     * @param ax the world x of A's local origin (px)
     * @param ay the world y of A's local origin (px)
     * @param ac cos of A's rotation
     * @param as sin of A's rotation
     * @param b shape B
     * @param bx the world x of B's local origin (px)
     * @param by the world y of B's local origin (px)
     * @param bc cos of B's rotation
     * @param bs sin of B's rotation
     * @param scratch receives the last part pair's contact (a scratch the caller owns)
     * @return whether some part of A overlaps some part of B
     */
    public boolean overlaps(Shape a, float ax, float ay, float ac, float as, Shape b, float bx,
            float by, float bc, float bs, Manifold scratch) {
        int na = a.getType() == Shape.TYPE_MULTI ? ((MultiShape) a).getShapeCount() : 1;
        int nb = b.getType() == Shape.TYPE_MULTI ? ((MultiShape) b).getShapeCount() : 1;
        for (int i = 0; i < na; i++) {
            Shape pa = a.getType() == Shape.TYPE_MULTI ? ((MultiShape) a).getShape(i) : a;
            for (int j = 0; j < nb; j++) {
                Shape pb = b.getType() == Shape.TYPE_MULTI ? ((MultiShape) b).getShape(j) : b;
                collide(pa, ax, ay, ac, as, pb, bx, by, bc, bs, 0f, scratch);
                if (scratch.pointCount > 0) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * Collides two circles: at most one point, with id 0. Coincident centres get the normal
     * (0, 1).
     *
     * @param a circle A
     * @param ax the world x of A's local origin (px)
     * @param ay the world y of A's local origin (px)
     * @param ac cos of A's rotation
     * @param as sin of A's rotation
     * @param b circle B
     * @param bx the world x of B's local origin (px)
     * @param by the world y of B's local origin (px)
     * @param bc cos of B's rotation
     * @param bs sin of B's rotation
     * @param speculativeDistance the largest gap still reported (px)
     * @param out receives the contact
     */
    public void collideCircles(Circle a, float ax, float ay, float ac, float as, Circle b,
            float bx, float by, float bc, float bs, float speculativeDistance, Manifold out) {
        apartGap = Float.NEGATIVE_INFINITY;
        float pax = ax + ac * a.getCenterX() - as * a.getCenterY();
        float pay = ay + as * a.getCenterX() + ac * a.getCenterY();
        float pbx = bx + bc * b.getCenterX() - bs * b.getCenterY();
        float pby = by + bs * b.getCenterX() + bc * b.getCenterY();
        float dx = pbx - pax;
        float dy = pby - pay;
        float ra = a.getRadius();
        float rb = b.getRadius();
        float distance = EMath.sqrt(dx * dx + dy * dy);
        float separation = distance - ra - rb;
        if (separation > speculativeDistance) {
            apartGap = separation;
            out.pointCount = 0;
            return;
        }
        float nx;
        float ny;
        if (distance > COINCIDENT_TOLERANCE * (ra + rb)) {
            nx = dx / distance;
            ny = dy / distance;
        } else {
            nx = 0f;
            ny = 1f;
        }
        out.normalX = nx;
        out.normalY = ny;
        // Midway between A's surface point (pa + ra·n) and B's (pb − rb·n).
        out.pointX[0] = 0.5f * (pax + ra * nx + pbx - rb * nx);
        out.pointY[0] = 0.5f * (pay + ra * ny + pby - rb * ny);
        out.separation[0] = separation;
        out.id[0] = 0;
        out.pointCount = 1;
    }

    /**
     * Collides a polygon A with a circle B: at most one point, with id 0. The normal is the
     * face normal when the circle's centre lies in front of a face or inside the polygon, and
     * the direction from the nearest vertex otherwise.
     *
     * @param a polygon A
     * @param ax the world x of A's local origin (px)
     * @param ay the world y of A's local origin (px)
     * @param ac cos of A's rotation
     * @param as sin of A's rotation
     * @param b circle B
     * @param bx the world x of B's local origin (px)
     * @param by the world y of B's local origin (px)
     * @param bc cos of B's rotation
     * @param bs sin of B's rotation
     * @param speculativeDistance the largest gap still reported (px)
     * @param out receives the contact
     */
    public void collidePolygonCircle(Polygon a, float ax, float ay, float ac, float as, Circle b,
            float bx, float by, float bc, float bs, float speculativeDistance, Manifold out) {
        apartGap = Float.NEGATIVE_INFINITY;
        // The circle's centre in A's local frame.
        float wx = bx + bc * b.getCenterX() - bs * b.getCenterY() - ax;
        float wy = by + bs * b.getCenterX() + bc * b.getCenterY() - ay;
        float cx = ac * wx + as * wy;
        float cy = -as * wx + ac * wy;
        float radius = b.getRadius();

        int n = a.getVertexCount();
        int face = 0;
        float faceSeparation = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            float s = a.getNormalX(i) * (cx - a.getVertexX(i))
                    + a.getNormalY(i) * (cy - a.getVertexY(i));
            if (s > faceSeparation) {
                faceSeparation = s;
                face = i;
            }
        }
        if (faceSeparation - radius > speculativeDistance) {
            apartGap = faceSeparation - radius;
            out.pointCount = 0;
            return;
        }

        int k = face + 1 == n ? 0 : face + 1;
        float v1x = a.getVertexX(face);
        float v1y = a.getVertexY(face);
        float v2x = a.getVertexX(k);
        float v2y = a.getVertexY(k);
        // The face of largest separation is the closest feature or one of its end vertices;
        // beyond an end (along the edge) the vertex is closest.
        boolean outside = faceSeparation > VERTEX_REGION_TOLERANCE * a.getBoundingRadius();
        float vx;
        float vy;
        if (outside && (cx - v1x) * (v2x - v1x) + (cy - v1y) * (v2y - v1y) < 0f) {
            vx = v1x;
            vy = v1y;
        } else if (outside && (cx - v2x) * (v1x - v2x) + (cy - v2y) * (v1y - v2y) < 0f) {
            vx = v2x;
            vy = v2y;
        } else {
            float nx = a.getNormalX(face);
            float ny = a.getNormalY(face);
            // Midway between the centre's projection on the face and the circle's deepest point.
            float px = cx - 0.5f * (faceSeparation + radius) * nx;
            float py = cy - 0.5f * (faceSeparation + radius) * ny;
            writeOnePoint(ax, ay, ac, as, nx, ny, px, py, faceSeparation - radius, out);
            return;
        }
        float dx = cx - vx;
        float dy = cy - vy;
        float distance = EMath.sqrt(dx * dx + dy * dy);
        if (distance - radius > speculativeDistance) {
            // The distance to the polygon: had the centre moved into a face's region, that face's
            // separation would be the distance, and the first test would find the shapes apart.
            apartGap = distance - radius;
            out.pointCount = 0;
            return;
        }
        float nx = dx / distance;
        float ny = dy / distance;
        float px = vx + 0.5f * (distance - radius) * nx;
        float py = vy + 0.5f * (distance - radius) * ny;
        writeOnePoint(ax, ay, ac, as, nx, ny, px, py, distance - radius, out);
    }

    /**
     * Collides two convex polygons by the separating-axis test and clipping (the Box2D v2.4 / v3
     * approach): one or two points. The reference face is the face of largest separation; A's
     * face is preferred unless B's separates by a small tolerance more, so the choice does not
     * flicker between ticks.
     *
     * @param a polygon A
     * @param ax the world x of A's local origin (px)
     * @param ay the world y of A's local origin (px)
     * @param ac cos of A's rotation
     * @param as sin of A's rotation
     * @param b polygon B
     * @param bx the world x of B's local origin (px)
     * @param by the world y of B's local origin (px)
     * @param bc cos of B's rotation
     * @param bs sin of B's rotation
     * @param speculativeDistance the largest gap still reported (px)
     * @param out receives the contact
     */
    public void collidePolygons(Polygon a, float ax, float ay, float ac, float as, Polygon b,
            float bx, float by, float bc, float bs, float speculativeDistance, Manifold out) {
        polygons.collide(a, ax, ay, ac, as, b, bx, by, bc, bs, speculativeDistance, out);
    }

    /**
     * Collides a landscape segment A with a circle or polygon B: one or two points whose normal
     * points from the segment to B. Which side B is on is decided, for every part of a multi-shape
     * alike, by its body's position (bx, by) for a faced segment, as in the original engine, and by
     * its body's centre of mass (sideX, sideY) for an unfaced one: a faced segment reports nothing
     * for a body on its open side. See {@link Segment} for the facing and the smoothing of joints.
     *
     * <p>Feature ids: a circle's point has id 0; a polygon's follow the polygon–polygon scheme, with
     * the segment as A and its ends numbered 0 and 1 (which end is 0 depends on the side B is on).
     *
     * @param a the segment, in world coordinates
     * @param b shape B, a circle or a polygon
     * @param bx the world x of B's local origin (px)
     * @param by the world y of B's local origin (px)
     * @param bc cos of B's rotation
     * @param bs sin of B's rotation
     * @param sideX the world x of B's body's centre of mass (px)
     * @param sideY the world y of B's body's centre of mass (px)
     * @param speculativeDistance the largest gap still reported (px)
     * @param out receives the contact
     * @throws IllegalArgumentException if B is not a circle or a polygon
     */
    public void collideSegment(Segment a, Shape b, float bx, float by, float bc, float bs, float sideX,
            float sideY, float speculativeDistance, Manifold out) {
        int tb = b.getType();
        if (tb == Shape.TYPE_POLYGON) {
            segments.collidePolygon(a, (Polygon) b, bx, by, bc, bs, sideX, sideY, speculativeDistance, out);
        } else if (tb == Shape.TYPE_CIRCLE) {
            segments.collideCircle(a, (Circle) b, bx, by, bc, bs, sideX, sideY, speculativeDistance, out);
        } else {
            throw new IllegalArgumentException("Collider.collideSegment: no narrowphase for shape type "
                    + tb + "; a multi-shape collides part by part");
        }
    }

    /**
     * The side of the segment the last {@link #collideSegment} call collided the shape from: +1 or
     * −1 as in {@link Segment#side}, 0 when the segment ignored the shape. Pass it back through
     * {@link Segment#side} while the contact persists.
     *
     * @return the side
     */
    public int getSegmentSide() {
        return segments.foundSide;
    }

    /**
     * After a collide that found the shapes apart (no points): the gap by the measure that decided
     * it, computed in A's frame: for two polygons the largest separation of B from one of A's faces,
     * else the distance between the shapes. Either changes by no more than any point of B moves, as
     * seen from A, so while none moves by the gap less the speculative distance, colliding the
     * shapes again finds them apart. Negative infinity after a collide that found points.
     *
     * @return the gap (px)
     */
    public float getApartGap() {
        return apartGap;
    }

    /** Writes a one-point manifold given in A's local frame, converting it to the world. */
    private static void writeOnePoint(float ax, float ay, float ac, float as, float nx, float ny,
            float px, float py, float separation, Manifold out) {
        out.normalX = ac * nx - as * ny;
        out.normalY = as * nx + ac * ny;
        out.pointX[0] = ax + ac * px - as * py;
        out.pointY[0] = ay + as * px + ac * py;
        out.separation[0] = separation;
        out.id[0] = 0;
        out.pointCount = 1;
    }
}
