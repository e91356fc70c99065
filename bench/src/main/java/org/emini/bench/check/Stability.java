package org.emini.bench.check;

import java.util.List;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.ShapeSpec;

/**
 * Did the scene stay what it should be? Judged from the bodies' poses in scene units (px), the same
 * way for every engine.
 *
 * <p>Stacking scenes (category {@code stacking}): every dynamic body should stay where it was put.
 * Sideways motion and turning are what a toppling stack shows; vertical motion is mostly the stack
 * settling on its contacts (soft contacts sag, Box2D's polygon skin lifts each row by about 1.5 cm).
 * With b the size of the first dynamic body: {@code stable} when every body stayed within b/4
 * sideways (5 px for a 20 px box, the scenario library's "still standing" margin), turned less than
 * 0.1 rad and moved less than b vertically; {@code collapsed} when a body moved more than b sideways
 * or 2b vertically, or turned more than 0.5 rad; {@code drifted} in between. Other scenes (rain into a container):
 * {@code stable} when no body left the container (outside the static bodies' horizontal extent or
 * below the top of the lowest static body) and every pose is finite, else {@code escaped}. Scenes
 * with joints: each joint's anchor is fixed in both bodies at the start; {@code stable} while the two
 * anchors stay within b/4 of each other, else {@code stretched}. A stacking scene with joints (the game
 * level: crates at rest and pendulums swinging beside them) gets both: {@code stretched} if a joint
 * fails, else the stacking verdict over the bodies no joint holds (the swinging ones move by design).
 *
 * <p>Motor-driven containers (the tumbler: a scene with a rotational motor): the container is the
 * motor's body, b the size of the first other dynamic body. A body escaped when its centre is
 * outside the container's outer bounding box in the container's own frame (it left through or sits
 * inside a wall). {@code stable} when nothing escaped, the pivot's joint holds to b/4 and the
 * container turns within 5% of the motor's target; else {@code escaped}, {@code stretched} or
 * {@code slowed}, in that order. Containers and the joint scenes' bodies are not judged against
 * the static bodies' extent.
 *
 * <p>Particles (Emini's, or the peers' circle bodies standing for them) are judged like rain: a
 * particle outside the static bodies' horizontal extent or below the top of the lowest static body
 * escaped; one with a non-finite position is non-finite. Their live count is reported.
 *
 * @param ticks ticks run before the check
 * @param verdict stable, drifted, collapsed, escaped, stretched, slowed or non-finite
 * @param maxDisplacementPx largest distance of a dynamic body from its initial position (px)
 * @param maxDxPx largest sideways displacement of a dynamic body (px)
 * @param maxDyPx largest vertical displacement of a dynamic body (px)
 * @param bodySize b, the size of the first dynamic body (px)
 * @param maxAngle largest |angle change| of a dynamic body (rad)
 * @param maxSpeed largest speed of a dynamic body at the check (px/s)
 * @param escaped dynamic bodies outside the container
 * @param nonFinite dynamic bodies with a non-finite pose
 * @param maxJointErrorPx largest distance between the two anchors of a joint (px), 0 without joints
 * @param motorSpeedError |ω − target| / |target| of the motor-driven container, 0 without one
 *     (NaN when the engine gave no angular velocities)
 * @param particles live particles
 * @param asleep dynamic bodies the engine had put to sleep, or -1 when the scene does not let bodies sleep
 */
public record Stability(long ticks, String verdict, double maxDisplacementPx, double maxDxPx, double maxDyPx, double bodySize,
                        double maxAngle, double maxSpeed, int escaped, int nonFinite,
                        double maxJointErrorPx, double motorSpeedError, int particles, int asleep) {

    /** The same check, with how many bodies the engine had put to sleep (-1: sleeping off). */
    public Stability withAsleep(int n) {
        return new Stability(ticks, verdict, maxDisplacementPx, maxDxPx, maxDyPx, bodySize, maxAngle, maxSpeed, escaped,
            nonFinite, maxJointErrorPx, motorSpeedError, particles, n);
    }

    /** Largest relative error of a motor-driven container's angular velocity still {@code stable}. */
    public static final double MOTOR_TOLERANCE = 0.05;

    /** Judges poses and angular velocities (scenes without particles). */
    public static Stability judge(Scenario s, long ticks, double[] initial, double[] now, double[] speeds, double[] omegas) {
        return judge(s, ticks, initial, now, speeds, omegas, null, 0);
    }

    /**
     * What moves in a scene, for the per-body figure: its dynamic bodies plus, for each particle
     * emitter, the particles it keeps alive (rate × lifetime, at most its pool).
     */
    public static long moving(Scenario s) {
        long n = s.bodies().stream().filter(b -> !b.state().isStatic()).count();
        if (s.elements().containsKey("particles")) {
            for (com.fasterxml.jackson.databind.JsonNode e : s.elements().get("particles").node()) {
                n += Math.min(e.path("maxCount").asInt(100), Math.round(e.path("rate").asDouble(20) * e.path("lifetime").asDouble(2)));
            }
        }
        return n;
    }

    /** Judges poses, without angular velocities (scenes without motors). */
    public static Stability judge(Scenario s, long ticks, double[] initial, double[] now, double[] speeds) {
        return judge(s, ticks, initial, now, speeds, null, null, 0);
    }

    /**
     * Judges poses.
     *
     * @param s the scene
     * @param ticks ticks run
     * @param initial poses at tick 0 (x, y, angle per body)
     * @param now poses now
     * @param speeds speeds now (px/s)
     * @param omegas angular velocities now (rad/s, scene sense), or null
     * @param particleXy x, y (px) of each live particle, or null
     * @param particleCount live particles
     */
    public static Stability judge(Scenario s, long ticks, double[] initial, double[] now, double[] speeds, double[] omegas,
                                  double[] particleXy, int particleCount) {
        double minX = Double.MAX_VALUE, maxX = -Double.MAX_VALUE, floorTop = -Double.MAX_VALUE;
        double size = 0;
        int container = -1;
        double target = 0;
        if (s.elements().containsKey("motors")) {
            for (com.fasterxml.jackson.databind.JsonNode m : s.elements().get("motors").node()) {
                if (container < 0 && m.has("angularVelocity")) {
                    container = index(s, m.get("body").asText());
                    target = m.get("angularVelocity").asDouble();
                }
            }
        }
        for (int i = 0; i < s.bodies().size(); i++) {
            BodySpec b = s.bodies().get(i);
            double[] wh = b.shape().size();
            double w = wh == null ? 0 : wh[0];
            double h = wh == null ? 0 : wh[1];
            if (b.state().isStatic()) {
                minX = Math.min(minX, b.x() - w / 2);
                maxX = Math.max(maxX, b.x() + w / 2);
                floorTop = Math.max(floorTop, b.y() - h / 2);
            } else if (size == 0 && i != container) {
                size = Math.max(w, h);
            }
        }
        boolean joints = s.elements().containsKey("joints");
        // The container's outer half extents in its own frame, and its pose now.
        double[] box = container >= 0 ? halfExtents(s.bodies().get(container).shape()) : null;
        double cc = container >= 0 ? Math.cos(now[3 * container + 2]) : 1;
        double cs = container >= 0 ? Math.sin(now[3 * container + 2]) : 0;
        boolean stacking = "stacking".equals(s.category());
        // A stacking scene with joints: the jointed bodies swing by design; the stacks are judged without them.
        java.util.Set<String> swinging = stacking && joints ? jointed(s) : java.util.Set.of();
        double maxD = 0, maxDx = 0, maxDy = 0, maxA = 0, maxV = 0;
        int escaped = 0, nonFinite = 0;
        for (int i = 0; i < s.bodies().size(); i++) {
            if (s.bodies().get(i).state().isStatic()) {
                continue;
            }
            double x = now[3 * i], y = now[3 * i + 1], a = now[3 * i + 2];
            if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(a)) {
                nonFinite++;
                continue;
            }
            maxV = Math.max(maxV, speeds[i]);
            if (swinging.contains(s.bodies().get(i).name())) {
                continue;
            }
            maxD = Math.max(maxD, Math.hypot(x - initial[3 * i], y - initial[3 * i + 1]));
            maxDx = Math.max(maxDx, Math.abs(x - initial[3 * i]));
            maxDy = Math.max(maxDy, Math.abs(y - initial[3 * i + 1]));
            maxA = Math.max(maxA, Math.abs(a - initial[3 * i + 2]));
            if (container >= 0) {
                if (i != container) {
                    double dx = x - now[3 * container], dy = y - now[3 * container + 1];
                    double lx = cc * dx + cs * dy, ly = -cs * dx + cc * dy;
                    if (!(Math.abs(lx) <= box[0] && Math.abs(ly) <= box[1])) {
                        escaped++;
                    }
                }
            } else if (!joints && minX <= maxX && (x < minX || x > maxX || y > floorTop)) {
                escaped++;
            }
        }
        for (int i = 0; i < particleCount; i++) {
            double x = particleXy[2 * i], y = particleXy[2 * i + 1];
            if (!Double.isFinite(x) || !Double.isFinite(y)) {
                nonFinite++;
            } else if (minX <= maxX && (x < minX || x > maxX || y > floorTop)) {
                escaped++;
            }
        }
        double jointError = jointError(s, initial, now);
        double motorError = 0;
        if (container >= 0) {
            motorError = omegas == null ? Double.NaN : Math.abs(omegas[container] - target) / Math.abs(target);
        }
        String verdict;
        if (nonFinite > 0 || Double.isNaN(jointError)) {
            verdict = "non-finite";
        } else if (container >= 0) {
            if (escaped > 0) {
                verdict = "escaped";
            } else if (jointError > size / 4) {
                verdict = "stretched";
            } else if (!(motorError <= MOTOR_TOLERANCE)) {
                verdict = "slowed";
            } else {
                verdict = "stable";
            }
        } else if (joints && (!stacking || jointError > size / 4)) {
            verdict = jointError <= size / 4 ? "stable" : "stretched";
        } else if (stacking) {
            if (maxDx <= size / 4 && maxA < 0.1 && maxDy <= size) {
                verdict = "stable";
            } else if (maxDx > size || maxDy > 2 * size || maxA > 0.5) {
                verdict = "collapsed";
            } else {
                verdict = "drifted";
            }
        } else {
            verdict = escaped == 0 ? "stable" : "escaped";
        }
        return new Stability(ticks, verdict, maxD, maxDx, maxDy, size, maxA, maxV, escaped, nonFinite, jointError, motorError,
            particleCount, -1);
    }

    /** The names of the bodies a joint holds. */
    private static java.util.Set<String> jointed(Scenario s) {
        java.util.Set<String> out = new java.util.HashSet<>();
        for (com.fasterxml.jackson.databind.JsonNode j : s.elements().get("joints").node()) {
            out.add(j.get("bodyA").asText());
            out.add(j.get("bodyB").asText());
        }
        return out;
    }

    private static int index(Scenario s, String name) {
        for (int i = 0; i < s.bodies().size(); i++) {
            if (s.bodies().get(i).name().equals(name)) {
                return i;
            }
        }
        throw new IllegalArgumentException("no body " + name);
    }

    /**
     * Half width and height of a shape's bounding box at angle 0 about its origin (px); a
     * multi-shape's from its parts, placed.
     */
    static double[] halfExtents(ShapeSpec shape) {
        double[] r = {0, 0};
        extents(shape, 0, 0, 0, r);
        return r;
    }

    private static void extents(ShapeSpec shape, double ox, double oy, double angle, double[] r) {
        double c = Math.cos(angle), sn = Math.sin(angle);
        if (shape.kind() == ShapeSpec.Kind.multiShape) {
            for (ShapeSpec.Part p : shape.parts()) {
                extents(p.shape(), ox + c * p.offsetX() - sn * p.offsetY(), oy + sn * p.offsetX() + c * p.offsetY(),
                    angle + p.angle(), r);
            }
            return;
        }
        if (shape.kind() == ShapeSpec.Kind.circle || shape.kind() == ShapeSpec.Kind.regularPolygon) {
            r[0] = Math.max(r[0], Math.abs(ox) + shape.radius());
            r[1] = Math.max(r[1], Math.abs(oy) + shape.radius());
            return;
        }
        List<double[]> v = shape.kind() == ShapeSpec.Kind.rectangle
            ? List.of(new double[] {-shape.width() / 2, -shape.height() / 2}, new double[] {shape.width() / 2, shape.height() / 2},
                new double[] {-shape.width() / 2, shape.height() / 2}, new double[] {shape.width() / 2, -shape.height() / 2})
            : shape.vertices();
        for (double[] p : v) {
            r[0] = Math.max(r[0], Math.abs(ox + c * p[0] - sn * p[1]));
            r[1] = Math.max(r[1], Math.abs(oy + sn * p[0] + c * p[1]));
        }
    }

    /** The largest anchor separation over the scene's joints (px); NaN if a pose is not finite. */
    private static double jointError(Scenario s, double[] initial, double[] now) {
        if (!s.elements().containsKey("joints")) {
            return 0;
        }
        java.util.Map<String, Integer> index = new java.util.HashMap<>();
        for (int i = 0; i < s.bodies().size(); i++) {
            index.put(s.bodies().get(i).name(), i);
        }
        double worst = 0;
        for (com.fasterxml.jackson.databind.JsonNode j : s.elements().get("joints").node()) {
            int a = index.get(j.get("bodyA").asText());
            int b = index.get(j.get("bodyB").asText());
            double[] la;
            double[] lb;
            if (j.has("at")) {
                double wx = j.get("at").get(0).asDouble(), wy = j.get("at").get(1).asDouble();
                la = toLocal(initial, a, wx, wy);
                lb = toLocal(initial, b, wx, wy);
            } else {
                la = anchor(j.path("anchorA"));
                lb = anchor(j.path("anchorB"));
            }
            double[] pa = toWorld(now, a, la);
            double[] pb = toWorld(now, b, lb);
            double d = Math.hypot(pa[0] - pb[0], pa[1] - pb[1]);
            if (Double.isNaN(d)) {
                return Double.NaN;
            }
            worst = Math.max(worst, d);
        }
        return worst;
    }

    private static double[] anchor(com.fasterxml.jackson.databind.JsonNode n) {
        return n.isArray() ? new double[] {n.get(0).asDouble(), n.get(1).asDouble()} : new double[] {0, 0};
    }

    private static double[] toLocal(double[] poses, int i, double wx, double wy) {
        double c = Math.cos(poses[3 * i + 2]), sn = Math.sin(poses[3 * i + 2]);
        double dx = wx - poses[3 * i], dy = wy - poses[3 * i + 1];
        return new double[] {c * dx + sn * dy, -sn * dx + c * dy};
    }

    private static double[] toWorld(double[] poses, int i, double[] l) {
        double c = Math.cos(poses[3 * i + 2]), sn = Math.sin(poses[3 * i + 2]);
        return new double[] {poses[3 * i] + c * l[0] - sn * l[1], poses[3 * i + 1] + sn * l[0] + c * l[1]};
    }
}
