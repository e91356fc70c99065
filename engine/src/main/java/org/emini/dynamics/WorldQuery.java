package org.emini.dynamics;

import org.emini.collision.IndexList;
import org.emini.collision.QueryCallback;
import org.emini.collision.RayCaster;
import org.emini.collision.ShapeCaster;
import org.emini.collision.SweptBox;
import org.emini.internal.HeapSort;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * The world's ray casts, shape casts, point and overlap queries ({@link Simulation#rayCast} and
 * the rest): the bodies near the query are found as {@link Simulation#queryBodies} finds them
 * (the last tick's simulated bodies one by one, the bodies moved since from the dirty list, static
 * and frozen ones through the broadphase) by their boxes swept along the cast, then tested exactly
 * in world order with {@link RayCaster} and {@link ShapeCaster}; landscape segments come from the
 * landscape's index, tested in index order after the bodies.
 *
 * <p>One per world; it owns its scratch, so a query allocates nothing once the candidate lists
 * have grown. A query's callbacks may not start another query of the same world (refused with an
 * {@link IllegalStateException}), but may read the world and call {@link Simulation#queryBodies}.
 */
final class WorldQuery {
    private final Simulation world;
    private final BodyQuery finder = new BodyQuery();
    private final RayCaster ray = new RayCaster(0f);
    private final ShapeCaster caster = new ShapeCaster();
    private final CastHit scratch = new CastHit();
    private final IndexList bodies = new IndexList();
    private final IndexList segments = new IndexList();
    private final float[] box = new float[4];
    private final SweptBox sweep = new SweptBox();
    private long[] order = new long[16];
    private String running;

    WorldQuery(Simulation world) {
        this.world = world;
    }

    /** Marks a query as running; a query started from its callbacks is refused. */
    void enter(String where) {
        if (running != null) {
            throw new IllegalStateException(where + ": called from the callback or filter of " + running
                + ", which is still running; collect what it reports and query after it returns");
        }
        running = where;
    }

    void exit() {
        running = null;
    }

    // ---------------------------------------------------------------------------------------------
    // Rays

    boolean rayCastClosest(float x1, float y1, float x2, float y2, QueryFilter filter, CastHit out) {
        out.clear();
        float dx = x2 - x1;
        float dy = y2 - y1;
        world.findBodies(finder, x1, y1, x1, y1, dx, dy, fresh(bodies));
        float best = Float.POSITIVE_INFINITY;
        for (int k = 0, n = bodies.count(); k < n; k++) {
            Body b = world.getBody(bodies.get(k));
            if (filter != null && !filter.accepts(b, -1)) {
                continue;
            }
            float ox = x1 - b.x;
            float oy = y1 - b.y;
            float ex = x2 - b.x;
            float ey = y2 - b.y;
            if (ray.shape(b.getShape(), b.c * ox + b.s * oy, -b.s * ox + b.c * oy, b.c * ex + b.s * ey,
                    -b.s * ex + b.c * ey) && ray.t < best) {
                best = ray.t;
                setBodyHit(out, b, ray.part);
            }
        }
        Landscape land = world.getLandscape();
        int n = gatherSegments(land, sweep.set(x1, y1, x1, y1, dx, dy));
        for (int k = 0; k < n; k++) {
            int seg = (int) order[k];
            if (filter != null && !filter.accepts(null, seg)) {
                continue;
            }
            if (raySegment(land, seg, x1, y1, x2, y2) && ray.t < best) {
                best = ray.t;
                out.set(null, 0, seg, ray.x, ray.y, ray.normalX, ray.normalY, ray.t);
            }
        }
        return out.hasHit();
    }

    void rayCast(float x1, float y1, float x2, float y2, CastCallback callback) {
        float dx = x2 - x1;
        float dy = y2 - y1;
        world.findBodies(finder, x1, y1, x1, y1, dx, dy, fresh(bodies));
        float end = 1f;
        for (int k = 0, n = bodies.count(); k < n; k++) {
            Body b = world.getBody(bodies.get(k));
            float ox = x1 - b.x;
            float oy = y1 - b.y;
            float ex = x2 - b.x;
            float ey = y2 - b.y;
            float lax = b.c * ox + b.s * oy;
            float lay = -b.s * ox + b.c * oy;
            float lbx = b.c * ex + b.s * ey;
            float lby = -b.s * ex + b.c * ey;
            Shape shape = b.getShape();
            for (int p = 0, parts = partCount(shape); p < parts; p++) {
                Shape part = part(shape, p);
                boolean hit = part.getType() == Shape.TYPE_CIRCLE ? ray.circle((Circle) part, lax, lay, lbx, lby)
                    : ray.polygon((Polygon) part, lax, lay, lbx, lby);
                if (hit && ray.t <= end) {
                    setBodyHit(scratch, b, p);
                    end = steer("World.rayCast", callback, end);
                    if (end == 0f) {
                        return;
                    }
                }
            }
        }
        Landscape land = world.getLandscape();
        int n = gatherSegments(land, sweep.set(x1, y1, x1, y1, dx, dy));
        for (int k = 0; k < n; k++) {
            int seg = (int) order[k];
            if (raySegment(land, seg, x1, y1, x2, y2) && ray.t <= end) {
                scratch.set(null, 0, seg, ray.x, ray.y, ray.normalX, ray.normalY, ray.t);
                end = steer("World.rayCast", callback, end);
                if (end == 0f) {
                    return;
                }
            }
        }
    }

    /** A body-local hit of the ray caster, back in the world. */
    private void setBodyHit(CastHit out, Body b, int part) {
        float hx = ray.x;
        float hy = ray.y;
        out.set(b, part, -1, b.x + b.c * hx - b.s * hy, b.y + b.s * hx + b.c * hy, b.c * ray.normalX - b.s * ray.normalY,
            b.s * ray.normalX + b.c * ray.normalY, ray.t);
    }

    /**
     * The ray against a landscape segment: a faced segment stops only rays that start on its
     * blocking side, as it stops only bodies whose position is there.
     */
    private boolean raySegment(Landscape land, int seg, float x1, float y1, float x2, float y2) {
        float sx = land.getStartX(seg);
        float sy = land.getStartY(seg);
        float ex = land.getEndX(seg);
        float ey = land.getEndY(seg);
        return blocks(land.getFace(seg), sx, sy, ex, ey, x1, y1) && ray.segment(sx, sy, ex, ey, x1, y1, x2, y2);
    }

    /** Whether a segment with this facing stops something whose position is (px, py). */
    private static boolean blocks(int face, float sx, float sy, float ex, float ey, float px, float py) {
        if (face == Landscape.FACE_NONE) {
            return true;
        }
        // (end − start) × (p − start): negative on the left, which FACE_LEFT blocks; the line blocks.
        float cross = (ex - sx) * (py - sy) - (ey - sy) * (px - sx);
        return face == Landscape.FACE_LEFT ? cross <= 0f : cross >= 0f;
    }

    /**
     * Calls the callback with the scratch hit and turns its answer into the cast's new end: 0 to
     * stop, a clip, or the end unchanged.
     */
    private float steer(String where, CastCallback callback, float end) {
        float answer = callback.reportHit(scratch);
        if (answer != answer) {
            throw new IllegalStateException(where + ": the callback returned NaN for " + scratch
                + "; return 0 to stop, a fraction to clip, -1 to ignore the hit or 1 to go on");
        }
        if (answer == 0f) {
            return 0f;
        }
        return answer > 0f && answer <= end ? answer : end;
    }

    // ---------------------------------------------------------------------------------------------
    // Shape casts

    boolean castShapeClosest(Shape shape, float x, float y, float c, float s, float dx, float dy, QueryFilter filter,
            CastHit out) {
        out.clear();
        shape.computeAabb(x, y, c, s, box);
        world.findBodies(finder, box[0], box[1], box[2], box[3], dx, dy, fresh(bodies));
        float best = Float.POSITIVE_INFINITY;
        for (int k = 0, n = bodies.count(); k < n; k++) {
            Body b = world.getBody(bodies.get(k));
            if (filter != null && !filter.accepts(b, -1)) {
                continue;
            }
            if (caster.cast(shape, x, y, c, s, dx, dy, b.getShape(), b.x, b.y, b.c, b.s) && caster.t < best) {
                best = caster.t;
                out.set(b, caster.part, -1, caster.x, caster.y, caster.normalX, caster.normalY, caster.t);
            }
        }
        Landscape land = world.getLandscape();
        int n = gatherSegments(land, sweep.set(box[0], box[1], box[2], box[3], dx, dy));
        for (int k = 0; k < n; k++) {
            int seg = (int) order[k];
            if (filter != null && !filter.accepts(null, seg)) {
                continue;
            }
            if (castSegment(land, seg, shape, x, y, c, s, dx, dy) && caster.t < best) {
                best = caster.t;
                out.set(null, 0, seg, caster.x, caster.y, caster.normalX, caster.normalY, caster.t);
            }
        }
        return out.hasHit();
    }

    void castShape(Shape shape, float x, float y, float c, float s, float dx, float dy, CastCallback callback) {
        shape.computeAabb(x, y, c, s, box);
        world.findBodies(finder, box[0], box[1], box[2], box[3], dx, dy, fresh(bodies));
        float end = 1f;
        for (int k = 0, n = bodies.count(); k < n; k++) {
            Body b = world.getBody(bodies.get(k));
            Shape target = b.getShape();
            for (int p = 0, parts = partCount(target); p < parts; p++) {
                if (caster.cast(shape, x, y, c, s, dx, dy, part(target, p), b.x, b.y, b.c, b.s) && caster.t <= end) {
                    scratch.set(b, p, -1, caster.x, caster.y, caster.normalX, caster.normalY, caster.t);
                    end = steer("World.castShape", callback, end);
                    if (end == 0f) {
                        return;
                    }
                }
            }
        }
        Landscape land = world.getLandscape();
        int n = gatherSegments(land, sweep.set(box[0], box[1], box[2], box[3], dx, dy));
        for (int k = 0; k < n; k++) {
            int seg = (int) order[k];
            if (castSegment(land, seg, shape, x, y, c, s, dx, dy) && caster.t <= end) {
                scratch.set(null, 0, seg, caster.x, caster.y, caster.normalX, caster.normalY, caster.t);
                end = steer("World.castShape", callback, end);
                if (end == 0f) {
                    return;
                }
            }
        }
    }

    /** A swept shape against a segment: a faced one stops it only when its position starts on the blocking side. */
    private boolean castSegment(Landscape land, int seg, Shape shape, float x, float y, float c, float s, float dx,
            float dy) {
        float sx = land.getStartX(seg);
        float sy = land.getStartY(seg);
        float ex = land.getEndX(seg);
        float ey = land.getEndY(seg);
        return blocks(land.getFace(seg), sx, sy, ex, ey, x, y) && caster.castSegment(shape, x, y, c, s, dx, dy, sx, sy,
            ex, ey);
    }

    // ---------------------------------------------------------------------------------------------
    // Points and overlaps

    /**
     * Reports the bodies that contain a point, in world order, until the callback says stop, and
     * returns the body it stopped at; without a callback, returns the first such body.
     */
    Body queryPoint(float x, float y, QueryCallback callback) {
        world.findBodies(finder, x, y, x, y, 0f, 0f, fresh(bodies));
        for (int k = 0, n = bodies.count(); k < n; k++) {
            int index = bodies.get(k);
            Body b = world.getBody(index);
            float ox = x - b.x;
            float oy = y - b.y;
            if (ray.contains(b.getShape(), b.c * ox + b.s * oy, -b.s * ox + b.c * oy)
                    && (callback == null || !callback.reportProxy(index))) {
                return b;
            }
        }
        return null;
    }

    void overlapShape(Shape shape, float x, float y, float c, float s, QueryCallback callback) {
        shape.computeAabb(x, y, c, s, box);
        world.findBodies(finder, box[0], box[1], box[2], box[3], 0f, 0f, fresh(bodies));
        for (int k = 0, n = bodies.count(); k < n; k++) {
            int index = bodies.get(k);
            Body b = world.getBody(index);
            if (caster.cast(shape, x, y, c, s, 0f, 0f, b.getShape(), b.x, b.y, b.c, b.s)
                    && !callback.reportProxy(index)) {
                return;
            }
        }
    }

    void overlapLandscape(Shape shape, float x, float y, float c, float s,
            QueryCallback callback) {
        shape.computeAabb(x, y, c, s, box);
        Landscape land = world.getLandscape();
        int n = gatherSegments(land, sweep.set(box[0], box[1], box[2], box[3], 0f, 0f));
        for (int k = 0; k < n; k++) {
            int seg = (int) order[k];
            if (caster.castSegment(shape, x, y, c, s, 0f, 0f, land.getStartX(seg), land.getStartY(seg),
                    land.getEndX(seg), land.getEndY(seg)) && !callback.reportProxy(seg)) {
                return;
            }
        }
    }

    // ---------------------------------------------------------------------------------------------

    /** The segments whose boxes the sweep meets, in index order, into order[0..n). */
    private int gatherSegments(Landscape land, SweptBox swept) {
        if (land.getSegmentCount() == 0) {
            return 0;
        }
        land.querySegments(swept, fresh(segments));
        int n = segments.count();
        if (order.length < n) {
            order = new long[Math.max(n, 2 * order.length)];
        }
        for (int i = 0; i < n; i++) {
            order[i] = segments.get(i);
        }
        HeapSort.sort(order, n);
        // Zero-length segments collide with nothing, as in the landscape.
        int kept = 0;
        for (int i = 0; i < n; i++) {
            int seg = (int) order[i];
            if (land.getStartX(seg) != land.getEndX(seg) || land.getStartY(seg) != land.getEndY(seg)) {
                order[kept++] = seg;
            }
        }
        return kept;
    }

    private static IndexList fresh(IndexList list) {
        list.clear();
        return list;
    }

    private static int partCount(Shape shape) {
        return shape.getType() == Shape.TYPE_MULTI ? ((MultiShape) shape).getShapeCount() : 1;
    }

    private static Shape part(Shape shape, int i) {
        return shape.getType() == Shape.TYPE_MULTI ? ((MultiShape) shape).getShape(i) : shape;
    }
}
