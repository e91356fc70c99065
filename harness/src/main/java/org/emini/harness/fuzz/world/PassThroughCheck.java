package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.List;
import org.emini.dynamics.Body;
import org.emini.dynamics.Landscape;
import org.emini.world.World;

/**
 * No dynamic body passes into or through a static body it collides with, or through a landscape
 * segment from a side the segment blocks. Each body is followed by its core, a point inside its shape
 * (the centroid; a multi-shape's largest part's), along the straight path from one tick to the next:
 *
 * <ul>
 *   <li>static bodies: the path, sampled at 9 points, must not come more than 0.5 px inside the static
 *   body's shape. Touching bodies overlap by well under 1 px, and the core lies inside its own body, so
 *   its entering another body at all means an overlap deeper than the body's own inner radius;</li>
 *   <li>landscape: the path must not cross a segment's line strictly within the segment from a side it
 *   blocks (both sides for faceless segments, the left or right of start → end for faced ones; a body
 *   coming from the open side passes, as the engine documents).</li>
 * </ul>
 *
 * A body meets a static body when both are interacting and share no collision layer and no joint or
 * spring links them (a link may pull a body into the static one by design, {@link Links}); the
 * landscape meets every dynamic body. Bodies frozen by the simulation area do not move, so they pass nothing.
 */
final class PassThroughCheck implements TickCheck {
    /** How far the core may come inside a static body (px). */
    static final double DEPTH = 0.5;
    private static final int SAMPLES = 8;

    private final List<Body> movers = new ArrayList<>();
    private final List<float[]> cores = new ArrayList<>();
    private final List<double[]> previous = new ArrayList<>();
    private final List<Body> walls = new ArrayList<>();
    private final List<float[]> wallBoxes = new ArrayList<>();
    private Links links;

    @Override
    public void start(FuzzWorld w) {
        links = new Links(w);
        World world = w.world();
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            if (b.isSensor()) {
                // Passes through everything, and everything through it, by design.
                continue;
            }
            if (b.isDynamic()) {
                movers.add(b);
                float[] core = ShapeDepth.core(b.getShape());
                cores.add(core);
                previous.add(at(b, core));
            } else if (b.isInteracting()) {
                float[] box = new float[4];
                b.getShape().computeAabb(b.getX(), b.getY(), b.getCos(), b.getSin(), box);
                walls.add(b);
                wallBoxes.add(box);
            }
        }
    }

    @Override
    public Violation afterTick(FuzzWorld w, int tick) {
        Violation found = null;
        for (int i = 0; i < movers.size() && found == null; i++) {
            Body b = movers.get(i);
            if (!w.inWorld(b)) {
                continue;
            }
            double[] p = previous.get(i);
            double[] q = at(b, cores.get(i));
            found = walls(w, tick, b, p, q);
            if (found == null) {
                found = landscape(w, tick, b, p, q);
            }
            previous.set(i, q);
        }
        return found;
    }

    private Violation walls(FuzzWorld w, int tick, Body b, double[] p, double[] q) {
        if (!b.isInteracting()) {
            return null;
        }
        for (int k = 0; k < walls.size(); k++) {
            Body s = walls.get(k);
            float[] box = wallBoxes.get(k);
            if ((s.getCollisionLayers() & b.getCollisionLayers()) != 0 || !filterAllows(b, s) || !w.inWorld(s)
                    || links.linked(b, s)
                    || Math.max(p[0], q[0]) < box[0] || Math.min(p[0], q[0]) > box[2]
                    || Math.max(p[1], q[1]) < box[1] || Math.min(p[1], q[1]) > box[3]) {
                continue;
            }
            for (int j = 0; j <= SAMPLES; j++) {
                double t = (double) j / SAMPLES;
                double x = p[0] + t * (q[0] - p[0]);
                double y = p[1] + t * (q[1] - p[1]);
                double depth = ShapeDepth.depth(s.getShape(), s.getX(), s.getY(), s.getCos(), s.getSin(), x, y);
                if (depth > DEPTH) {
                    return new Violation(ViolationKind.PASS_THROUGH, tick, String.format(
                            "%s's core moved from (%.4f, %.4f) to (%.4f, %.4f), %.3f px deep into %s (bound %.1f px); "
                                    + "velocity (%.4g, %.4g)", w.name(b), p[0], p[1], q[0], q[1], depth, w.name(s), DEPTH,
                            b.getVelocityX(), b.getVelocityY()));
                }
            }
        }
        return null;
    }

    /** Box2D's filter rule, as the engine applies it beside the layers. */
    static boolean filterAllows(Body a, Body b) {
        if (a.getGroupIndex() == b.getGroupIndex() && a.getGroupIndex() != 0) {
            return a.getGroupIndex() > 0;
        }
        return (a.getMaskBits() & b.getCategoryBits()) != 0 && (a.getCategoryBits() & b.getMaskBits()) != 0;
    }

    private static Violation landscape(FuzzWorld w, int tick, Body b, double[] p, double[] q) {
        Landscape land = w.world().getLandscape();
        for (int k = 0; k < land.getSegmentCount(); k++) {
            double ax = land.getStartX(k);
            double ay = land.getStartY(k);
            double bx = land.getEndX(k);
            double by = land.getEndY(k);
            double from = orient(ax, ay, bx, by, p[0], p[1]);
            double to = orient(ax, ay, bx, by, q[0], q[1]);
            if (!(from < 0 && to > 0 || from > 0 && to < 0)) {
                continue;
            }
            double d3 = orient(p[0], p[1], q[0], q[1], ax, ay);
            double d4 = orient(p[0], p[1], q[0], q[1], bx, by);
            boolean within = d3 <= 0 && d4 >= 0 || d3 >= 0 && d4 <= 0;
            int face = land.getFace(k);
            // FACE_LEFT blocks the side where (end − start) × (p − start) < 0, FACE_RIGHT the other.
            boolean blocked = face == Landscape.FACE_NONE || face == Landscape.FACE_LEFT && from < 0
                    || face == Landscape.FACE_RIGHT && from > 0;
            if (within && blocked) {
                return new Violation(ViolationKind.PASS_THROUGH, tick, String.format(
                        "%s's core crossed landscape segment %d (%.4g, %.4g) → (%.4g, %.4g), face %d, moving from "
                                + "(%.4f, %.4f) to (%.4f, %.4f); velocity (%.4g, %.4g)", w.name(b), k, ax, ay, bx, by, face,
                        p[0], p[1], q[0], q[1], b.getVelocityX(), b.getVelocityY()));
            }
        }
        return null;
    }

    private static double orient(double ax, double ay, double bx, double by, double cx, double cy) {
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    }

    private static double[] at(Body b, float[] core) {
        return new double[] {b.toWorldX(core[0], core[1]), b.toWorldY(core[0], core[1])};
    }
}
