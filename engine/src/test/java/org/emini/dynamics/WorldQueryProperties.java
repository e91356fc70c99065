package org.emini.dynamics;

import static org.emini.dynamics.QueryModel.Convex;
import static org.emini.dynamics.QueryModel.point;
import static org.emini.dynamics.QueryModel.sd;
import static org.emini.dynamics.QueryModel.segment;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.emini.Flavour;
import org.emini.math.EMath;
import org.emini.shape.Circle;
import org.emini.shape.InvalidShapeException;
import org.emini.shape.MultiShape;
import org.emini.shape.Shape;
import org.emini.world.World;

/**
 * Every query of the world against {@link QueryModel}, a brute-force model in double precision that
 * tests every body part and landscape segment directly, on random worlds: circles (centred and
 * off-centre), rectangles, random convex polygons (some off-centre), multi-shapes of both, static
 * and dynamic, after a few ticks (so the solver has moved the simulated ones), some frozen outside
 * a simulation area, some moved by the application since the last tick, one removed; landscape
 * segments, some chained, some faced.
 *
 * <p>Tolerance: {@link #TOL} = 32 float roundings (ulps) of 1024 px, the largest coordinate in
 * these worlds, about 0.004 px: the engine computes in float, the model in double, so results may
 * differ by a few roundings of each coordinate through a few dozen operations. A check never
 * compares ill-conditioned numbers (such as the fraction of a ray that grazes a circle): it asks
 * whether the engine's answer is geometrically right within TOL, e.g. that at the reported fraction
 * the shape touches what it hit within TOL and that nothing overlapped the way up to there by more
 * than TOL; where the model's answer is within TOL of a boundary (a point within TOL of a surface),
 * either answer is accepted. Fixed seeds, so CI sees the same worlds every run.
 */
class WorldQueryProperties {
    // 32 float ulps at 1024 px; in the double flavour 1e-10 px (32 double ulps, 7e-12, was exceeded by
    // a 630 px ray whose hit lay 8.1e-12 px off the surface).
    static final double TOL = Flavour.DOUBLE ? 1e-10 : 32 * Math.ulp(1024f);

    // ------------------------------------------------------------------------------ random worlds

    static Shape randomShape(Random r) {
        switch (r.nextInt(7)) {
            case 0:
                return Shape.createCircle(3f + 25f * r.nextFloat());
            case 1: {
                float radius = 3f + 20f * r.nextFloat();
                return new Circle(radius, (r.nextFloat() - 0.5f) * 40f, (r.nextFloat() - 0.5f) * 40f);
            }
            case 2:
                return Shape.createRectangle(2f + 50f * r.nextFloat(), 2f + 50f * r.nextFloat());
            case 3:
                return polygon(r, 0f, 0f);
            case 4:
                return polygon(r, (r.nextFloat() - 0.5f) * 50f, (r.nextFloat() - 0.5f) * 50f);
            default: {
                int n = 2 + r.nextInt(2);
                Shape[] parts = new Shape[n];
                for (int i = 0; i < n; i++) {
                    float ox = (r.nextFloat() - 0.5f) * 50f;
                    float oy = (r.nextFloat() - 0.5f) * 50f;
                    parts[i] = r.nextBoolean() ? new Circle(3f + 12f * r.nextFloat(), ox, oy) : polygon(r, ox, oy);
                }
                return new MultiShape(parts);
            }
        }
    }

    /** Points on a random ellipse at jittered increasing angles (convex position), moved off the origin. */
    static Shape polygon(Random r, float ox, float oy) {
        int n = 3 + r.nextInt(Shape.MAX_VERTICES - 2);
        float a = 4f + 25f * r.nextFloat();
        float b = a * (0.3f + 0.7f * r.nextFloat());
        float turn = 6.28f * r.nextFloat();
        float[] xy = new float[2 * n];
        for (int i = 0; i < n; i++) {
            double angle = (i + 0.7 * (r.nextDouble() - 0.5)) * 2 * Math.PI / n;
            double x = a * Math.cos(angle);
            double y = b * Math.sin(angle);
            xy[2 * i] = ox + (float) (x * Math.cos(turn) - y * Math.sin(turn));
            xy[2 * i + 1] = oy + (float) (x * Math.sin(turn) + y * Math.cos(turn));
        }
        try {
            return Shape.createPolygon(xy);
        } catch (InvalidShapeException e) {
            return Shape.createRectangle(a, b);
        }
    }

    static World randomWorld(Random r) {
        World w = new World();
        int n = 5 + r.nextInt(40);
        for (int i = 0; i < n; i++) {
            Body b = new Body(-300f + 600f * r.nextFloat(), -300f + 600f * r.nextFloat(), randomShape(r), r.nextInt(3) > 0);
            b.setAngle(-4f + 8f * r.nextFloat());
            float vx = -100f + 200f * r.nextFloat();
            float vy = -100f + 200f * r.nextFloat();
            if (b.isDynamic()) {
                b.setVelocity(vx, vy);
            }
            w.addBody(b);
        }
        Landscape land = w.getLandscape();
        int segments = r.nextInt(16);
        float cx = -300f + 600f * r.nextFloat();
        float cy = -300f + 600f * r.nextFloat();
        for (int i = 0; i < segments; i++) {
            float nx;
            float ny;
            if (r.nextInt(3) == 0) {
                // Chained: start where the last one ended.
                nx = cx + (r.nextFloat() - 0.5f) * 200f;
                ny = cy + (r.nextFloat() - 0.5f) * 200f;
            } else {
                cx = -300f + 600f * r.nextFloat();
                cy = -300f + 600f * r.nextFloat();
                nx = cx + (r.nextFloat() - 0.5f) * 300f;
                ny = cy + (r.nextFloat() - 0.5f) * 300f;
            }
            if (nx != cx || ny != cy) {
                land.addSegment(cx, cy, nx, ny, r.nextInt(3));
            }
            cx = nx;
            cy = ny;
        }
        if (r.nextBoolean()) {
            float x = -300f + 300f * r.nextFloat();
            w.setSimulationArea(x, -400f, x + 300f, 400f);
        }
        for (int t = r.nextInt(4); t > 0; t--) {
            w.tick();
        }
        // Moved by the application since the last tick (on the dirty list), and one body removed.
        for (int k = r.nextInt(4); k > 0 && w.getBodyCount() > 0; k--) {
            Body b = w.getBody(r.nextInt(w.getBodyCount()));
            b.setPosition(-300f + 600f * r.nextFloat(), -300f + 600f * r.nextFloat());
            b.setAngle(6f * r.nextFloat());
        }
        if (r.nextBoolean() && w.getBodyCount() > 1) {
            w.removeBody(w.getBody(r.nextInt(w.getBodyCount())));
        }
        return w;
    }

    // ------------------------------------------------------------------------------ targets

    /** A body part or a landscape segment, as the model sees it. */
    static final class Target {
        final int body;
        final int part;
        final int segment;
        final Convex convex;
        /** For a faced segment: whether it stops something starting where the query starts, and whether that is in doubt. */
        boolean blocks = true;
        boolean doubtful;

        Target(int body, int part, int segment, Convex convex) {
            this.body = body;
            this.part = part;
            this.segment = segment;
            this.convex = convex;
        }

        @Override
        public String toString() {
            return segment >= 0 ? "segment " + segment : "body " + body + " part " + part;
        }
    }

    /** Every body part and every landscape segment, the faced ones judged from (ox, oy). */
    static List<Target> targets(World w, double ox, double oy, QueryFilter filter) {
        List<Target> out = new ArrayList<>();
        for (int i = 0; i < w.getBodyCount(); i++) {
            Body b = w.getBody(i);
            if (filter != null && !filter.accepts(b, -1)) {
                continue;
            }
            List<Convex> parts = QueryModel.bodyParts(b);
            for (int p = 0; p < parts.size(); p++) {
                out.add(new Target(i, p, -1, parts.get(p)));
            }
        }
        Landscape land = w.getLandscape();
        for (int s = 0; s < land.getSegmentCount(); s++) {
            if (filter != null && !filter.accepts(null, s)) {
                continue;
            }
            double x1 = land.getStartX(s);
            double y1 = land.getStartY(s);
            double x2 = land.getEndX(s);
            double y2 = land.getEndY(s);
            Target t = new Target(-1, 0, s, segment(x1, y1, x2, y2));
            int face = land.getFace(s);
            if (face != Landscape.FACE_NONE) {
                double len = Math.hypot(x2 - x1, y2 - y1);
                double side = ((x2 - x1) * (oy - y1) - (y2 - y1) * (ox - x1)) / len;
                t.blocks = face == Landscape.FACE_LEFT ? side <= 0 : side >= 0;
                t.doubtful = Math.abs(side) <= TOL;
            }
            out.add(t);
        }
        return out;
    }

    static Target find(List<Target> all, World w, CastHit hit) {
        int body = -1;
        if (hit.getBody() != null) {
            for (int i = 0; i < w.getBodyCount(); i++) {
                if (w.getBody(i) == hit.getBody()) {
                    body = i;
                }
            }
        }
        for (Target t : all) {
            if (hit.getBody() != null ? t.body == body && t.part == hit.getPart() : t.segment == hit.getSegment()) {
                return t;
            }
        }
        return null;
    }

    static QueryFilter randomFilter(Random r) {
        switch (r.nextInt(3)) {
            case 0:
                return null;
            case 1:
                return (body, segment) -> body != null ? body.getId() % 3 != 0 : segment % 2 == 0;
            default:
                return (body, segment) -> body != null && body.isDynamic();
        }
    }

    // ------------------------------------------------------------------------------ the checks

    /** The closest hit of a cast (a ray: a point shape) against the model. */
    static void checkClosest(String what, List<Convex> moving, double dx, double dy, List<Target> all, World w,
            boolean got, CastHit hit) {
        double te = got ? hit.getFraction() : 1;
        assertTrue(te >= 0 && te <= 1, what + ": fraction " + te);
        if (te > 0) {
            // Nothing was overlapped on the way to the hit by more than TOL.
            List<Convex> swept = QueryModel.sweep(moving, te * dx, te * dy);
            for (Target t : all) {
                if (t.blocks && !t.doubtful) {
                    double s = sd(swept, t.convex);
                    assertTrue(s >= -TOL, what + ": " + t + " overlapped by " + -s + " px before the hit " + hit);
                }
            }
        }
        if (!got) {
            return;
        }
        Target x = find(all, w, hit);
        assertNotNull(x, what + ": hit something filtered out or unknown: " + hit);
        assertTrue(x.blocks || x.doubtful, what + ": hit a faced segment from its open side: " + hit);
        checkHitOn(what, moving, dx, dy, x.convex, hit);
    }

    /** A hit at its fraction: touching, with the point on both and the normal separating them. */
    static void checkHitOn(String what, List<Convex> moving, double dx, double dy, Convex x, CastHit hit) {
        double te = hit.getFraction();
        List<Convex> at = QueryModel.translate(moving, te * dx, te * dy);
        double nx = hit.getNormalX();
        double ny = hit.getNormalY();
        assertEquals(1.0, Math.hypot(nx, ny), 1e-5, what + ": normal not unit " + hit);
        double s = sd(at, x);
        if (te > 0) {
            assertTrue(Math.abs(s) <= TOL, what + ": at the hit the distance is " + s + ", " + hit);
            Convex p = point(hit.getX(), hit.getY());
            assertTrue(Math.abs(sd(p, x)) <= TOL, what + ": point off the surface by " + sd(p, x) + ", " + hit);
            assertTrue(sd(at, p) <= TOL, what + ": point off the moving shape by " + sd(at, p) + ", " + hit);
            // Some moving part touches what was hit, the normal separating the two (the other parts
            // of a concave multi-shape may lie beside it).
            double sep = Double.NEGATIVE_INFINITY;
            for (Convex part : at) {
                if (Math.abs(sd(part, x)) <= TOL) {
                    sep = Math.max(sep, QueryModel.separationAlong(part, x, nx, ny));
                }
            }
            assertTrue(sep >= -TOL, what + ": the normal does not separate them (" + sep + "), " + hit);
        } else {
            assertTrue(s <= TOL, what + ": at fraction 0 the distance is " + s + ", " + hit);
            {
                // Overlapping at the start (a ray starting inside): the normal is the shortest way
                // out for one of the moving parts that overlaps.
                boolean some = false;
                for (Convex part : moving) {
                    double depth = sd(part, x);
                    if (depth <= TOL && QueryModel.separationAlong(part, x, nx, ny) >= depth - TOL) {
                        some = true;
                    }
                }
                assertTrue(some, what + ": the normal is no shortest way out, " + hit);
            }
        }
    }

    /** Every hit of a cast with a callback that goes on: the hits are exactly the targets on the way. */
    static void checkAll(String what, List<Convex> moving, double dx, double dy, List<Target> all, World w,
            List<CastHit> hits) {
        List<Convex> swept = QueryModel.sweep(moving, dx, dy);
        // Order: bodies by index and part, then segments by index, each once.
        long last = Long.MIN_VALUE;
        for (CastHit h : hits) {
            Target t = find(all, w, h);
            assertNotNull(t, what + ": unknown hit " + h);
            long key = t.segment >= 0 ? (1L << 40) + t.segment : ((long) t.body << 8) + t.part;
            assertTrue(key > last, what + ": out of order or twice: " + h);
            last = key;
            assertTrue(t.blocks || t.doubtful, what + ": hit a faced segment from its open side: " + h);
            double te = h.getFraction();
            if (te > 0) {
                double s = sd(QueryModel.sweep(moving, te * dx, te * dy), t.convex);
                assertTrue(s >= -TOL, what + ": " + t + " overlapped by " + -s + " px before its hit " + h);
            }
            checkHitOn(what, moving, dx, dy, t.convex, h);
        }
        for (Target t : all) {
            if (!t.blocks && !t.doubtful) {
                continue;
            }
            double s = sd(swept, t.convex);
            boolean reported = false;
            for (CastHit h : hits) {
                reported |= find(all, w, h) == t;
            }
            if (s < -TOL && !t.doubtful) {
                assertTrue(reported, what + ": missed " + t + " (overlapped by " + -s + " px)");
            }
            if (s > TOL) {
                assertTrue(!reported, what + ": reported " + t + " that stays " + s + " px away");
            }
        }
    }

    static List<CastHit> collect(boolean ray, World w, float a, float b, float c, float d, Shape shape, float angle) {
        List<CastHit> hits = new ArrayList<>();
        CastCallback keep = h -> {
            hits.add(new CastHit().set(h));
            return 1f;
        };
        if (ray) {
            w.rayCast(a, b, c, d, keep);
        } else {
            w.castShape(shape, a, b, angle, c, d, keep);
        }
        return hits;
    }

    // ------------------------------------------------------------------------------ properties

    @Property(tries = 60, seed = "1717")
    void raysMatchTheBruteForceModel(@ForAll long seed) {
        Random r = new Random(seed);
        World w = randomWorld(r);
        CastHit hit = new CastHit();
        for (int q = 0; q < 30; q++) {
            float x1 = -350f + 700f * r.nextFloat();
            float y1 = -350f + 700f * r.nextFloat();
            float x2 = -350f + 700f * r.nextFloat();
            float y2 = -350f + 700f * r.nextFloat();
            if (q % 10 == 1 && w.getBodyCount() > 0) {
                // From a body's origin: often inside it.
                Body b = w.getBody(r.nextInt(w.getBodyCount()));
                x1 = b.getX();
                y1 = b.getY();
            } else if (q % 10 == 2) {
                x2 = x1;
                y2 = y1;
            } else if (q % 10 == 3) {
                x2 = x1 + 20f * (r.nextFloat() - 0.5f);
                y2 = y1 + 20f * (r.nextFloat() - 0.5f);
            }
            String what = "seed " + seed + " ray (" + x1 + ", " + y1 + ") to (" + x2 + ", " + y2 + ")";
            List<Convex> ray = List.of(point(x1, y1));
            QueryFilter filter = randomFilter(r);
            boolean got = w.rayCastClosest(x1, y1, x2, y2, filter, hit);
            checkClosest(what, ray, x2 - x1, y2 - y1, targets(w, x1, y1, filter), w, got, hit);
            List<CastHit> hits = collect(true, w, x1, y1, x2, y2, null, 0f);
            checkAll(what + " (all hits)", ray, x2 - x1, y2 - y1, targets(w, x1, y1, null), w, hits);
        }
    }

    @Property(tries = 60, seed = "1718")
    void shapeCastsMatchTheBruteForceModel(@ForAll long seed) {
        Random r = new Random(seed);
        World w = randomWorld(r);
        CastHit hit = new CastHit();
        for (int q = 0; q < 20; q++) {
            Shape shape = randomShape(r);
            float x = -350f + 700f * r.nextFloat();
            float y = -350f + 700f * r.nextFloat();
            float angle = 6.28f * r.nextFloat();
            float dx = 500f * (r.nextFloat() - 0.5f);
            float dy = 500f * (r.nextFloat() - 0.5f);
            if (q % 5 == 1) {
                dx = 0f;
                dy = 0f;
            }
            String what = "seed " + seed + " cast " + shape + " from (" + x + ", " + y + ") angle " + angle + " by (" + dx
                + ", " + dy + ")";
            List<Convex> moving = QueryModel.parts(shape, x, y, EMath.cos(angle), EMath.sin(angle));
            QueryFilter filter = randomFilter(r);
            boolean got = w.castShapeClosest(shape, x, y, angle, dx, dy, filter, hit);
            checkClosest(what, moving, dx, dy, targets(w, x, y, filter), w, got, hit);
            List<CastHit> hits = collect(false, w, x, y, dx, dy, shape, angle);
            checkAll(what + " (all hits)", moving, dx, dy, targets(w, x, y, null), w, hits);
        }
    }

    @Property(tries = 60, seed = "1719")
    void pointAndOverlapQueriesMatchTheBruteForceModel(@ForAll long seed) {
        Random r = new Random(seed);
        World w = randomWorld(r);
        for (int q = 0; q < 20; q++) {
            float x = -350f + 700f * r.nextFloat();
            float y = -350f + 700f * r.nextFloat();
            if (q % 2 == 0 && w.getBodyCount() > 0) {
                Body b = w.getBody(r.nextInt(w.getBodyCount()));
                x = b.getX() + 10f * (r.nextFloat() - 0.5f);
                y = b.getY() + 10f * (r.nextFloat() - 0.5f);
            }
            String what = "seed " + seed + " point (" + x + ", " + y + ")";
            List<Integer> found = new ArrayList<>();
            w.queryPoint(x, y, i -> found.add(i) || true);
            checkSet(what, found, w, List.of(point(x, y)));
            Body first = w.findBodyAt(x, y);
            assertEquals(found.isEmpty() ? null : w.getBody(found.get(0)), first, what + ": findBodyAt");

            Shape shape = randomShape(r);
            float angle = 6.28f * r.nextFloat();
            List<Convex> placed = QueryModel.parts(shape, x, y, EMath.cos(angle), EMath.sin(angle));
            List<Integer> overlapping = new ArrayList<>();
            w.overlapShape(shape, x, y, angle, i -> overlapping.add(i) || true);
            checkSet(what + " overlap " + shape + " angle " + angle, overlapping, w, placed);
            List<Integer> segments = new ArrayList<>();
            w.overlapLandscape(shape, x, y, angle, i -> segments.add(i) || true);
            Landscape land = w.getLandscape();
            for (int s = 0; s < land.getSegmentCount(); s++) {
                double d = sd(placed, segment(land.getStartX(s), land.getStartY(s), land.getEndX(s), land.getEndY(s)));
                checkMember(what + " overlapLandscape " + shape + " segment " + s, segments.contains(s), d);
            }
            assertEquals(segments.stream().sorted().distinct().toList(), segments, what + ": segment order");
        }
    }

    /** The bodies reported are those the model finds within 0 of the shape, in world order. */
    static void checkSet(String what, List<Integer> found, World w, List<Convex> shape) {
        assertEquals(found.stream().sorted().distinct().toList(), found, what + ": order");
        for (int i = 0; i < w.getBodyCount(); i++) {
            double d = sd(shape, QueryModel.bodyParts(w.getBody(i)));
            checkMember(what + " body " + i, found.contains(i), d);
        }
    }

    static void checkMember(String what, boolean reported, double distance) {
        if (distance < -TOL) {
            assertTrue(reported, what + " overlaps by " + -distance + " px but was not reported");
        } else if (distance > TOL) {
            assertTrue(!reported, what + " is " + distance + " px away but was reported");
        }
    }
}
