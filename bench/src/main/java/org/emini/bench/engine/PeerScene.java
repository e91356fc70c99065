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

    final double timestep;
    final int iterations;
    final double gravityX;
    final double gravityY;
    final List<PeerBody> bodies = new ArrayList<>();
    final List<PeerJoint> joints = new ArrayList<>();

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

    /** A shape in metres (y up): a circle, or a convex polygon with counter-clockwise vertices. */
    static final class PeerShape {
        final boolean circle;
        final double radius;
        final double[] xy;
        final double density;
        final double friction;
        final double restitution;

        PeerShape(boolean circle, double radius, double[] xy, double density, double friction, double restitution) {
            this.circle = circle;
            this.radius = radius;
            this.xy = xy;
            this.density = density;
            this.friction = friction;
            this.restitution = restitution;
        }

        int vertexCount() {
            return xy.length / 2;
        }
    }

    /** A body in metres, y up. */
    static final class PeerBody {
        final String name;
        final PeerShape shape;
        final boolean dynamic;
        final double x;
        final double y;
        final double angle;
        final double vx;
        final double vy;
        final double omega;
        final boolean rotatable;
        final boolean gravity;

        PeerBody(String name, PeerShape shape, BodySpec spec) {
            BodyState s = spec.state();
            this.name = name;
            this.shape = shape;
            this.dynamic = !s.isStatic();
            this.x = spec.x() / PX_PER_M;
            this.y = -spec.y() / PX_PER_M;
            this.angle = -s.angle();
            this.vx = s.vx() / PX_PER_M;
            this.vy = -s.vy() / PX_PER_M;
            this.omega = -s.angularVelocity();
            this.rotatable = s.rotatable();
            this.gravity = s.gravity();
        }
    }

    private PeerScene(Scenario s) {
        timestep = s.world().timestep();
        iterations = s.world().iterations();
        gravityX = s.world().gravityX() / PX_PER_M;
        gravityY = -s.world().gravityY() / PX_PER_M;
    }

    /**
     * Translates a scene.
     *
     * @param engine the engine's name, for messages
     * @param maxVertices the engine's polygon vertex limit
     */
    static PeerScene of(Scenario s, String engine, int maxVertices) throws UnsupportedSceneException {
        for (String element : s.elements().keySet()) {
            if (!"joints".equals(element)) {
                throw new UnsupportedSceneException("the " + engine + " adapter does not build " + element + " yet");
            }
        }
        if (!s.actions().isEmpty()) {
            throw new UnsupportedSceneException("the " + engine + " adapter does not play actions");
        }
        if (s.world().dampingLateral() != 0 || s.world().dampingRotational() != 0) {
            throw new UnsupportedSceneException("the " + engine + " adapter does not map per-tick damping");
        }
        PeerScene p = new PeerScene(s);
        Map<ShapeSpec, PeerShape> shapes = new IdentityHashMap<>();
        for (BodySpec b : s.bodies()) {
            BodyState st = b.state();
            if (!st.interacting() || !st.layers().isEmpty()) {
                throw new UnsupportedSceneException("the " + engine + " adapter does not map collision layers or non-interacting bodies (" + b.name() + ")");
            }
            PeerShape shape = shapes.get(b.shape());
            if (shape == null) {
                shape = shape(b.shape(), engine, maxVertices);
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
        return p;
    }

    private static PeerShape shape(ShapeSpec spec, String engine, int maxVertices) throws UnsupportedSceneException {
        double friction = spec.friction() * spec.friction();
        double e = spec.elasticity();
        switch (spec.kind()) {
            case circle: {
                double r = spec.radius() / PX_PER_M;
                return new PeerShape(true, r, null, spec.mass() / (Math.PI * r * r), friction, e);
            }
            case rectangle: {
                double w = spec.width() / 2, h = spec.height() / 2;
                return polygon(new double[] {-w, -h, w, -h, w, h, -w, h}, spec, friction, e, engine, maxVertices);
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
                return polygon(xy, spec, friction, e, engine, maxVertices);
            }
            case polygon: {
                double[] xy = new double[2 * spec.vertices().size()];
                for (int i = 0; i < spec.vertices().size(); i++) {
                    xy[2 * i] = spec.vertices().get(i)[0];
                    xy[2 * i + 1] = spec.vertices().get(i)[1];
                }
                return polygon(xy, spec, friction, e, engine, maxVertices);
            }
            default:
                throw new UnsupportedSceneException("the " + engine + " adapter does not build " + spec.kind() + " shapes yet");
        }
    }

    /** From px, y down, either winding, to metres, y up, counter-clockwise. */
    private static PeerShape polygon(double[] px, ShapeSpec spec, double friction, double e, String engine, int maxVertices)
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
        if (Math.abs(cx / (3 * area2)) > 1e-6 || Math.abs(cy / (3 * area2)) > 1e-6) {
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
        return new PeerShape(false, 0, m, spec.mass() / (area2 / 2), friction, e);
    }
}
