package org.emini.bench.engine;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.BodyState;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.ShapeSpec;

/**
 * A scene translated for the metre-based engines (dyn4j, Box2D): {@value #PX_PER_M} px per metre, y
 * up, angles growing counter-clockwise. A 20 px box becomes a 1 m box and gravity 200 px/s² becomes
 * 10 m/s², the sizes these engines are tuned for.
 *
 * <p>Materials: Emini combines the friction of a contact as the product of the two shapes' factors,
 * Box2D and dyn4j as the square root of the product; each shape's friction is squared here so every
 * engine gets the same contact friction. Mass becomes a density (mass / area in m²), so masses and
 * inertias match.
 */
final class PeerScene {
    /** Pixels per metre. */
    static final double PX_PER_M = 20.0;

    /**
     * Writes a peer body's pose, given in the peers' frame (metres, y up, angles counter-clockwise),
     * into a pose array in the scene's (pixels, y down, angles clockwise): the one conversion every
     * peer adapter uses.
     */
    static void putPose(double[] out, int i, double xMetres, double yMetres, double angle) {
        out[3 * i] = xMetres * PX_PER_M;
        out[3 * i + 1] = -yMetres * PX_PER_M;
        out[3 * i + 2] = -angle;
    }

    /** A peer body's speed, given in metres per second, in pixels per second. */
    static double speedPx(double vxMetres, double vyMetres) {
        return Math.hypot(vxMetres, vyMetres) * PX_PER_M;
    }

    final double timestep;
    final int iterations;
    final double gravityX;
    final double gravityY;
    /**
     * Whether the scene lets bodies sleep ({@code world.sleeping}): the peers then sleep at their own
     * tolerances (bench/ENGINES.md, Sleeping); a scene that sets tolerances is refused.
     */
    final boolean sleeping;
    final List<PeerBody> bodies = new ArrayList<>();
    final List<PeerJoint> joints = new ArrayList<>();
    final List<PeerMotor> motors = new ArrayList<>();
    final List<PeerEmitter> emitters = new ArrayList<>();

    /** Radius of a particle's circle body (m): 2 px, a tenth of a metre. */
    static final double PARTICLE_RADIUS = 2 / PX_PER_M;
    /** Collision category of particle bodies; scene bodies keep category 1. */
    static final int PARTICLE_CATEGORY = 0x0002;
    /** What particle bodies meet: the scene's bodies (category 1), never each other. */
    static final int PARTICLE_MASK = 0x0001;

    /**
     * A particle emitter fixed in the world, in metres, y up, for engines without particles: its
     * particles become small circle bodies (see {@link PeerParticles}). Angles counter-clockwise
     * from +x; spreads are the full widths of uniform deviations, as in the scene.
     */
    static final class PeerEmitter {
        final double x1;
        final double y1;
        final double x2;
        final double y2;
        final int maxCount;
        final double rate;
        final double rateSpread;
        final double lifetime;
        final double lifetimeSpread;
        final double speed;
        final double speedSpread;
        final double angle;
        final double angleSpread;
        final double restitution;
        final double gravityScale;
        final boolean collide;
        final long seed;

        PeerEmitter(com.fasterxml.jackson.databind.JsonNode n, int index) {
            com.fasterxml.jackson.databind.JsonNode from = n.get("from");
            com.fasterxml.jackson.databind.JsonNode to = n.has("to") ? n.get("to") : from;
            x1 = from.get(0).asDouble() / PX_PER_M;
            y1 = -from.get(1).asDouble() / PX_PER_M;
            x2 = to.get(0).asDouble() / PX_PER_M;
            y2 = -to.get(1).asDouble() / PX_PER_M;
            maxCount = n.path("maxCount").asInt(100);
            rate = n.path("rate").asDouble(20);
            rateSpread = n.path("rateSpread").asDouble(0);
            lifetime = n.path("lifetime").asDouble(2);
            lifetimeSpread = n.path("lifetimeSpread").asDouble(0);
            speed = n.path("speed").asDouble(10) / PX_PER_M;
            speedSpread = n.path("speedSpread").asDouble(0) / PX_PER_M;
            angle = -Math.toRadians(n.path("angleDeg").asDouble(0));
            angleSpread = Math.toRadians(n.path("angleSpreadDeg").asDouble(0));
            restitution = n.path("elasticity").asDouble(1);
            gravityScale = n.path("gravityFactor").asDouble(1);
            collide = n.path("collide").asBoolean(true);
            seed = n.has("seed") ? n.get("seed").asLong() : 0x5DEECE66DL + index;
        }
    }

    /**
     * A pin joint (revolute) or, when fixed, a weld, at one world point (m, y up) of the start pose.
     * Bodies are indices into {@link #bodies}.
     */
    static final class PeerJoint {
        final int a;
        final int b;
        final double x;
        final double y;
        final boolean fixed;
        final boolean collide;

        PeerJoint(int a, int b, double x, double y, boolean fixed, boolean collide) {
            this.a = a;
            this.b = b;
            this.x = x;
            this.y = y;
            this.fixed = fixed;
            this.collide = collide;
        }
    }

    /**
     * A convex shape in metres (y up), in its body's frame: a circle (centred at cx, cy), or a
     * convex polygon with counter-clockwise vertices. A body has one, or one per part of a
     * multi-shape.
     */
    static final class PeerShape {
        final boolean circle;
        final double radius;
        final double cx;
        final double cy;
        final double[] xy;
        final double density;
        final double friction;
        final double restitution;

        PeerShape(boolean circle, double radius, double[] xy, double density, double friction, double restitution) {
            this(circle, radius, 0, 0, xy, density, friction, restitution);
        }

        PeerShape(boolean circle, double radius, double cx, double cy, double[] xy, double density, double friction,
                  double restitution) {
            this.circle = circle;
            this.radius = radius;
            this.cx = cx;
            this.cy = cy;
            this.xy = xy;
            this.density = density;
            this.friction = friction;
            this.restitution = restitution;
        }

        int vertexCount() {
            return xy.length / 2;
        }
    }

    /**
     * A rotational motor, mapped onto the revolute joint that pins its body to a static body (the
     * peers' motors are joint motors: they drive the relative angular velocity of the joint's two
     * bodies, which against a static body is the body's own, as Emini's single-body motor drives).
     * Index into {@link #joints}; speed in rad/s counter-clockwise, relative to the joint's body b
     * minus body a; torque cap in N·m (kg·m²/s²).
     */
    static final class PeerMotor {
        final int joint;
        final double speed;
        final double maxTorque;

        PeerMotor(int joint, double speed, double maxTorque) {
            this.joint = joint;
            this.speed = speed;
            this.maxTorque = maxTorque;
        }
    }

    /** A body in metres, y up. */
    static final class PeerBody {
        final String name;
        /** The body's shape, or its first part for a multi-shape. */
        final PeerShape shape;
        /** Every convex part (one for a plain shape). */
        final List<PeerShape> parts;
        final boolean dynamic;
        final double x;
        final double y;
        final double angle;
        final double vx;
        final double vy;
        final double omega;
        final boolean rotatable;
        final boolean gravity;
        /** Whether the body may sleep ({@code sleepingAllowed}), when the scene lets bodies sleep. */
        final boolean sleepingAllowed;

        PeerBody(String name, List<PeerShape> parts, BodySpec spec) {
            BodyState s = spec.state();
            this.name = name;
            this.shape = parts.get(0);
            this.parts = parts;
            this.dynamic = !s.isStatic();
            this.x = spec.x() / PX_PER_M;
            this.y = -spec.y() / PX_PER_M;
            this.angle = -s.angle();
            this.vx = s.vx() / PX_PER_M;
            this.vy = -s.vy() / PX_PER_M;
            this.omega = -s.angularVelocity();
            this.rotatable = s.rotatable();
            this.gravity = s.gravity();
            this.sleepingAllowed = s.sleepingAllowed();
        }
    }

    private PeerScene(Scenario s) {
        timestep = s.world().timestep();
        iterations = s.world().iterations();
        gravityX = s.world().gravityX() / PX_PER_M;
        gravityY = -s.world().gravityY() / PX_PER_M;
        sleeping = s.world().sleeping().enabled();
    }

    /**
     * Translates a scene.
     *
     * @param engine the engine's name, for messages
     * @param maxVertices the engine's polygon vertex limit
     */
    static PeerScene of(Scenario s, String engine, int maxVertices) throws UnsupportedSceneException {
        for (String element : s.elements().keySet()) {
            if (!"joints".equals(element) && !"motors".equals(element) && !"particles".equals(element)) {
                throw new UnsupportedSceneException("the " + engine + " adapter does not build " + element + " yet");
            }
        }
        if (!s.actions().isEmpty()) {
            throw new UnsupportedSceneException("the " + engine + " adapter does not play actions");
        }
        if (s.world().dampingLateral() != 0 || s.world().dampingRotational() != 0) {
            throw new UnsupportedSceneException("the " + engine + " adapter does not map per-tick damping");
        }
        org.emini.harness.scenario.SleepSpec sleep = s.world().sleeping();
        if (sleep.enabled() && !(Double.isNaN(sleep.linearTolerance()) && Double.isNaN(sleep.angularTolerance())
                && Double.isNaN(sleep.timeToSleep()))) {
            throw new UnsupportedSceneException("the " + engine + " adapter sleeps at the engine's own tolerances; "
                + "the scene sets Emini's (world.sleeping)");
        }
        PeerScene p = new PeerScene(s);
        Map<ShapeSpec, List<PeerShape>> shapes = new IdentityHashMap<>();
        for (BodySpec b : s.bodies()) {
            BodyState st = b.state();
            if (!st.interacting() || !st.layers().isEmpty()) {
                throw new UnsupportedSceneException("the " + engine + " adapter does not map collision layers or non-interacting bodies (" + b.name() + ")");
            }
            List<PeerShape> shape = shapes.get(b.shape());
            if (shape == null) {
                shape = b.shape().kind() == ShapeSpec.Kind.multiShape
                    ? multiShape(b.shape(), engine, maxVertices)
                    : List.of(shape(b.shape(), engine, maxVertices));
                shapes.put(b.shape(), shape);
            }
            p.bodies.add(new PeerBody(b.name(), shape, b));
        }
        if (s.elements().containsKey("joints")) {
            java.util.Map<String, Integer> index = new java.util.HashMap<>();
            for (int i = 0; i < s.bodies().size(); i++) {
                index.put(s.bodies().get(i).name(), i);
            }
            for (com.fasterxml.jackson.databind.JsonNode j : s.elements().get("joints").node()) {
                int a = index.get(j.get("bodyA").asText());
                int b = index.get(j.get("bodyB").asText());
                double wx, wy;
                if (j.has("at")) {
                    wx = j.get("at").get(0).asDouble();
                    wy = j.get("at").get(1).asDouble();
                } else {
                    // A's local anchor placed by A's start pose (B's anchor coincides for a pin joint).
                    BodySpec ba = s.bodies().get(a);
                    com.fasterxml.jackson.databind.JsonNode la = j.path("anchorA");
                    double lx = la.isArray() ? la.get(0).asDouble() : 0, ly = la.isArray() ? la.get(1).asDouble() : 0;
                    double c = Math.cos(ba.state().angle()), sn = Math.sin(ba.state().angle());
                    wx = ba.x() + c * lx - sn * ly;
                    wy = ba.y() + sn * lx + c * ly;
                }
                p.joints.add(new PeerJoint(a, b, wx / PX_PER_M, -wy / PX_PER_M, j.path("fixed").asBoolean(false),
                    j.path("collide").asBoolean(false)));
            }
        }
        if (s.elements().containsKey("motors")) {
            for (com.fasterxml.jackson.databind.JsonNode m : s.elements().get("motors").node()) {
                p.motors.add(motor(s, p, m, engine));
            }
        }
        if (s.elements().containsKey("particles")) {
            int i = 0;
            for (com.fasterxml.jackson.databind.JsonNode n : s.elements().get("particles").node()) {
                if (n.has("body")) {
                    throw new UnsupportedSceneException("the " + engine + " adapter emits particles from fixed points only");
                }
                if (n.path("damping").asDouble(0) != 0) {
                    throw new UnsupportedSceneException("the " + engine + " adapter does not map particle damping");
                }
                p.emitters.add(new PeerEmitter(n, i++));
            }
        }
        return p;
    }

    /**
     * A rotational motor on a body pinned (a loose joint) to a static body becomes that joint's
     * motor. The scene's cap is an impulse per tick (px units); the joint's is a torque: divided by
     * the timestep and by {@value #PX_PER_M}² (mass is unchanged, px² become m²). The scene's ω grows
     * clockwise on the screen, the peers' counter-clockwise: negated.
     */
    private static PeerMotor motor(Scenario s, PeerScene p, com.fasterxml.jackson.databind.JsonNode m, String engine)
            throws UnsupportedSceneException {
        String body = m.get("body").asText();
        if (m.has("velocity") || !m.has("angularVelocity")) {
            throw new UnsupportedSceneException("the " + engine + " adapter maps rotational motors only (" + body + ")");
        }
        int k = -1;
        for (int i = 0; i < s.bodies().size(); i++) {
            if (s.bodies().get(i).name().equals(body)) {
                k = i;
            }
        }
        for (int j = 0; j < p.joints.size(); j++) {
            PeerJoint pj = p.joints.get(j);
            int other = pj.a == k ? pj.b : pj.b == k ? pj.a : -1;
            if (other >= 0 && !pj.fixed && !p.bodies.get(other).dynamic) {
                double omega = -m.get("angularVelocity").asDouble();
                double torque = m.get("maxImpulse").asDouble() / p.timestep / (PX_PER_M * PX_PER_M);
                // The joint motor drives ω_b − ω_a; with a static a that is the body's ω.
                return new PeerMotor(j, pj.b == k ? omega : -omega, torque);
            }
        }
        throw new UnsupportedSceneException("the " + engine + " adapter maps a motor onto the joint that pins its body to a static body;"
            + " " + body + " has none");
    }

    /**
     * The parts of a multi-shape, each placed in the body's frame (turned by the part's angle, moved
     * by its offset), with the multi-shape's friction and elasticity (Emini's multi-shapes use their
     * own material for every part) and each part's own mass as a density (scaled so the parts add up
     * to the multi-shape's mass). The mass-weighted centroid must be the shape origin.
     */
    private static List<PeerShape> multiShape(ShapeSpec spec, String engine, int maxVertices) throws UnsupportedSceneException {
        List<ShapeSpec.Part> flat = new ArrayList<>();
        List<double[]> place = new ArrayList<>();
        flatten(spec, 0, 0, 0, flat, place);
        double total = 0;
        for (ShapeSpec.Part part : flat) {
            total += part.shape().mass();
        }
        double scale = total > 0 ? spec.mass() / total : 1;
        double friction = spec.friction() * spec.friction();
        List<PeerShape> out = new ArrayList<>();
        double mx = 0, my = 0, m = 0;
        for (int i = 0; i < flat.size(); i++) {
            ShapeSpec part = flat.get(i).shape();
            double[] t = place.get(i);
            double c = Math.cos(t[2]), sn = Math.sin(t[2]);
            double mass = part.mass() * scale;
            PeerShape ps;
            if (part.kind() == ShapeSpec.Kind.circle) {
                double r = part.radius() / PX_PER_M;
                ps = new PeerShape(true, r, t[0] / PX_PER_M, -t[1] / PX_PER_M, null, mass / (Math.PI * r * r), friction,
                    spec.elasticity());
                mx += mass * t[0];
                my += mass * t[1];
            } else {
                double[] local = vertices(part);
                double[] xy = new double[local.length];
                for (int v = 0; v < local.length / 2; v++) {
                    xy[2 * v] = t[0] + c * local[2 * v] - sn * local[2 * v + 1];
                    xy[2 * v + 1] = t[1] + sn * local[2 * v] + c * local[2 * v + 1];
                }
                ps = polygon(xy, part, mass, friction, spec.elasticity(), engine, maxVertices, false);
                double[] cen = centroid(xy);
                mx += mass * cen[0];
                my += mass * cen[1];
            }
            m += mass;
            out.add(ps);
        }
        if (Math.abs(mx / m) > 1e-6 || Math.abs(my / m) > 1e-6) {
            throw new UnsupportedSceneException("multi-shape centre of mass is not at the shape origin (" + spec.name()
                + "): bodies would turn about different points");
        }
        return out;
    }

    private static void flatten(ShapeSpec spec, double dx, double dy, double angle, List<ShapeSpec.Part> flat, List<double[]> place) {
        double c = Math.cos(angle), sn = Math.sin(angle);
        for (ShapeSpec.Part p : spec.parts()) {
            double x = dx + c * p.offsetX() - sn * p.offsetY(), y = dy + sn * p.offsetX() + c * p.offsetY();
            if (p.shape().kind() == ShapeSpec.Kind.multiShape) {
                flatten(p.shape(), x, y, angle + p.angle(), flat, place);
            } else {
                flat.add(p);
                place.add(new double[] {x, y, angle + p.angle()});
            }
        }
    }

    /** A polygon's centroid (px, either winding). */
    private static double[] centroid(double[] xy) {
        int n = xy.length / 2;
        double a = 0, cx = 0, cy = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double cross = xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
            a += cross;
            cx += (xy[2 * i] + xy[2 * j]) * cross;
            cy += (xy[2 * i + 1] + xy[2 * j + 1]) * cross;
        }
        return new double[] {cx / (3 * a), cy / (3 * a)};
    }

    private static PeerShape shape(ShapeSpec spec, String engine, int maxVertices) throws UnsupportedSceneException {
        double friction = spec.friction() * spec.friction();
        double e = spec.elasticity();
        switch (spec.kind()) {
            case circle: {
                double r = spec.radius() / PX_PER_M;
                return new PeerShape(true, r, null, spec.mass() / (Math.PI * r * r), friction, e);
            }
            case rectangle:
            case regularPolygon:
            case polygon:
                return polygon(vertices(spec), spec, spec.mass(), friction, e, engine, maxVertices, true);
            default:
                throw new UnsupportedSceneException("the " + engine + " adapter does not build " + spec.kind() + " shapes yet");
        }
    }

    /** A polygon shape's vertices in px around its origin, as Emini makes them. */
    private static double[] vertices(ShapeSpec spec) {
        switch (spec.kind()) {
            case rectangle: {
                double w = spec.width() / 2, h = spec.height() / 2;
                return new double[] {-w, -h, w, -h, w, h, -w, h};
            }
            case regularPolygon: {
                int n = spec.sides();
                double[] xy = new double[2 * n];
                for (int i = 0; i < n; i++) {
                    // Emini's vertex i is at angle 2πi/n in its own (float) arithmetic.
                    float a = (float) (2 * Math.PI) * i / n;
                    xy[2 * i] = spec.radius() * Math.cos(a);
                    xy[2 * i + 1] = spec.radius() * Math.sin(a);
                }
                return xy;
            }
            default: {
                double[] xy = new double[2 * spec.vertices().size()];
                for (int i = 0; i < spec.vertices().size(); i++) {
                    xy[2 * i] = spec.vertices().get(i)[0];
                    xy[2 * i + 1] = spec.vertices().get(i)[1];
                }
                return xy;
            }
        }
    }

    /**
     * From px, y down, either winding, to metres, y up, counter-clockwise. A body's own polygon must
     * have its centroid at the origin ({@code centred}); a multi-shape's part need not.
     */
    private static PeerShape polygon(double[] px, ShapeSpec spec, double mass, double friction, double e, String engine,
                                     int maxVertices, boolean centred)
            throws UnsupportedSceneException {
        int n = px.length / 2;
        if (n > maxVertices) {
            throw new UnsupportedSceneException(engine + " polygons have at most " + maxVertices + " vertices, the scene has " + n);
        }
        double[] m = new double[px.length];
        for (int i = 0; i < n; i++) {
            m[2 * i] = px[2 * i] / PX_PER_M;
            m[2 * i + 1] = -px[2 * i + 1] / PX_PER_M;
        }
        double area2 = 0;
        double cx = 0, cy = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double cross = m[2 * i] * m[2 * j + 1] - m[2 * j] * m[2 * i + 1];
            area2 += cross;
            cx += (m[2 * i] + m[2 * j]) * cross;
            cy += (m[2 * i + 1] + m[2 * j + 1]) * cross;
        }
        if (centred && (Math.abs(cx / (3 * area2)) > 1e-6 || Math.abs(cy / (3 * area2)) > 1e-6)) {
            // Emini rotates a body about its shape's origin, dyn4j and Box2D about the centroid.
            throw new UnsupportedSceneException("polygon centroid is not at the shape origin (" + spec.name() + "): bodies would turn about different points");
        }
        if (area2 < 0) {
            double[] r = new double[m.length];
            for (int i = 0; i < n; i++) {
                r[2 * i] = m[2 * (n - 1 - i)];
                r[2 * i + 1] = m[2 * (n - 1 - i) + 1];
            }
            m = r;
            area2 = -area2;
        }
        return new PeerShape(false, 0, m, mass / (area2 / 2), friction, e);
    }
}
