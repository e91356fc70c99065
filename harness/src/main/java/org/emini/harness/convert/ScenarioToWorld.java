package org.emini.harness.convert;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.emini.harness.scenario.ActionSpec;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.BodyState;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.Section;
import org.emini.harness.scenario.ShapeSpec;
import org.emini.harness.scenario.WorldSpec;
import org.emini.io.PhyBody;
import org.emini.io.PhyFixed;
import org.emini.io.PhyJoint;
import org.emini.io.PhyLandscape;
import org.emini.io.PhyMotor;
import org.emini.io.PhyMultiShape;
import org.emini.io.PhyPairConstraint;
import org.emini.io.PhyParticleEmitter;
import org.emini.io.PhySegment;
import org.emini.io.PhyShape;
import org.emini.io.PhySpring;
import org.emini.io.PhyVector;
import org.emini.io.PhyWorld;
import org.emini.io.PhyWorldSettings;

/**
 * A scene as an original world file (version 10), where the format allows: world gravity and
 * damping, shapes, bodies (named in their user data as {@code name=...}), joints, springs, motors,
 * landscape and particle emitters, with the mapping of org/emini/io/phy-mapping.md run backwards
 * (angular velocities negated, values rounded to the nearest fixed-point step). What a world file
 * cannot hold (timestep, iterations, solver settings, actions, expectations, spring damping, ...)
 * is listed.
 */
public final class ScenarioToWorld {
    /** The user-data prefix that carries a body's scene name. */
    static final String NAME_KEY = "name=";

    /**
     * The world file's document and what did not carry over.
     *
     * @param world the document (version 10)
     * @param notConverted elements left out, one line each
     * @param approximated elements written in another form, one line each
     */
    public record Result(PhyWorld world, List<String> notConverted, List<String> approximated) {
    }

    /** An element that cannot be written; the message says why. */
    private static final class Skip extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Skip(String message) {
            super(message, null, false, false);
        }
    }

    private final Scenario scene;
    private final PhyWorld doc = new PhyWorld();
    private final List<String> notConverted = new ArrayList<>();
    private final List<String> approximated = new ArrayList<>();
    private final Map<ShapeSpec, Integer> shapes = new IdentityHashMap<>();
    private final Map<String, Integer> bodies = new HashMap<>();

    private ScenarioToWorld(Scenario scene) {
        this.scene = scene;
    }

    /** Converts a loaded scene. */
    public static Result convert(Scenario scene) {
        ScenarioToWorld c = new ScenarioToWorld(scene);
        c.world();
        for (BodySpec b : scene.bodies()) {
            c.attempt("body " + b.name(), () -> c.body(b));
        }
        for (Map.Entry<String, Section> e : scene.elements().entrySet()) {
            c.element(e.getKey(), e.getValue().node());
        }
        for (ActionSpec a : scene.actions()) {
            c.notConverted.add("action at " + YamlText.num(a.at()) + " s: " + a.kind()
                    + (a.body() != null ? " on " + a.body() : ""));
        }
        c.notConverted.add("run, record, expectations and references (a world file holds none)");
        return new Result(c.doc, List.copyOf(c.notConverted), List.copyOf(c.approximated));
    }

    private void attempt(String what, Runnable r) {
        try {
            r.run();
        } catch (Skip e) {
            notConverted.add(what + ": " + e.getMessage());
        }
    }

    private void world() {
        WorldSpec w = scene.world();
        PhyWorldSettings s = new PhyWorldSettings();
        attempt("world", () -> {
            s.setGravity(vec(w.gravityX(), w.gravityY()));
            s.setDampingLinearRaw(fx(w.dampingLateral()));
            s.setDampingRotationalRaw(fx(w.dampingRotational()));
        });
        doc.setSettings(s);
        if (Math.abs(w.timestep() - 0.05) > 1e-12) {
            notConverted.add("world timestep " + YamlText.num(w.timestep()) + " s (a loaded world uses 1/20 s)");
        }
        if (w.iterations() != WorldSpec.DEFAULT.iterations() || w.dynamicIterations()) {
            notConverted.add("world iterations " + w.iterations() + (w.dynamicIterations() ? ", dynamic" : "")
                    + " (a loaded world uses 10, fixed)");
        }
        if (!w.solver().isEmpty()) {
            notConverted.add("world solver settings " + w.solver().keySet());
        }
        if (w.sleeping().enabled()) {
            notConverted.add("world sleeping (the original engine has none)");
        }
    }

    /** The shape-list index of a scene shape, adding it (and a multishape's parts) on first use. */
    private int shape(ShapeSpec spec) {
        Integer known = shapes.get(spec);
        if (known != null) {
            return known;
        }
        int index;
        if (spec.kind() == ShapeSpec.Kind.multiShape) {
            int[] parts = new int[spec.parts().size()];
            double mass = 0;
            for (int i = 0; i < parts.length; i++) {
                ShapeSpec.Part p = spec.parts().get(i);
                parts[i] = part(p);
                mass += p.shape().mass();
            }
            if (Math.abs(spec.mass() - mass) > 1e-9 * Math.max(1, mass)) {
                approximated.add("shape " + label(spec) + ": mass " + YamlText.num(spec.mass())
                        + " written as its parts' sum " + YamlText.num(mass));
            }
            if (spec.friction() != 0.25 || spec.elasticity() != 0) {
                approximated.add("shape " + label(spec) + ": a multishape's material is the default (friction 0.25, "
                        + "elasticity 0) in the original");
            }
            index = add(new PhyMultiShape(parts));
        } else {
            index = add(standard(spec, 0, 0, 0));
        }
        shapes.put(spec, index);
        return index;
    }

    private int part(ShapeSpec.Part p) {
        if (p.offsetX() == 0 && p.offsetY() == 0 && p.angle() == 0) {
            return shape(p.shape());
        }
        if (p.shape().kind() == ShapeSpec.Kind.multiShape) {
            throw new Skip("a multishape part that is itself a multishape, moved or turned");
        }
        return add(standard(p.shape(), p.offsetX(), p.offsetY(), p.angle()));
    }

    private int add(org.emini.io.PhyShapeBase s) {
        if (doc.getShapes().size() >= PhyWorld.NONE) {
            throw new Skip("more than 255 shapes: a body cannot name it");
        }
        doc.getShapes().add(s);
        return doc.getShapes().size() - 1;
    }

    /** A circle or polygon, its vertices moved by (dx, dy) and turned by angle (a multishape part). */
    private PhyShape standard(ShapeSpec spec, double dx, double dy, double angle) {
        double[] xy;
        switch (spec.kind()) {
            case circle -> {
                if (dx != 0 || dy != 0) {
                    throw new Skip("a circle part off the origin (the original centres circles on it)");
                }
                xy = new double[] {0, spec.radius()};
                if (spec.radius() != Math.floor(spec.radius())) {
                    approximated.add("shape " + label(spec) + ": radius " + YamlText.num(spec.radius())
                            + " (the original truncates it to " + (long) spec.radius() + " px)");
                }
            }
            case rectangle -> {
                double w = spec.width() / 2;
                double h = spec.height() / 2;
                // The original's createRectangle order.
                xy = new double[] {-w, -h, -w, h, w, h, w, -h};
            }
            case regularPolygon -> {
                int n = spec.sides();
                xy = new double[2 * n];
                for (int k = 0; k < n; k++) {
                    // The engine's vertices (angle 2πk/n), listed in the original's winding.
                    double a = -2 * Math.PI * k / n;
                    xy[2 * k] = spec.radius() * Math.cos(a);
                    xy[2 * k + 1] = spec.radius() * Math.sin(a);
                }
            }
            case polygon -> {
                xy = new double[2 * spec.vertices().size()];
                for (int k = 0; k < spec.vertices().size(); k++) {
                    xy[2 * k] = spec.vertices().get(k)[0];
                    xy[2 * k + 1] = spec.vertices().get(k)[1];
                }
                if (winding(xy) < 0) {
                    xy = reversed(xy);
                }
            }
            default -> throw new Skip("a multishape inside a multishape");
        }
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        PhyVector[] vs = new PhyVector[xy.length / 2];
        for (int k = 0; k < vs.length; k++) {
            vs[k] = vec(dx + c * xy[2 * k] - s * xy[2 * k + 1], dy + s * xy[2 * k] + c * xy[2 * k + 1]);
        }
        PhyShape shape = new PhyShape(vs);
        shape.setMassRaw(fx(spec.mass()));
        shape.setFrictionRaw(fx(spec.friction()));
        shape.setElasticityRaw(fx(spec.elasticity()));
        return shape;
    }

    /** The original's winding test: Σ x(i+1)·y(i) − y(i+1)·x(i), positive for its vertex order. */
    private static double winding(double[] xy) {
        double sum = 0;
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            sum += xy[2 * j] * xy[2 * i + 1] - xy[2 * j + 1] * xy[2 * i];
        }
        return sum;
    }

    private static double[] reversed(double[] xy) {
        double[] r = new double[xy.length];
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            r[2 * i] = xy[2 * (n - 1 - i)];
            r[2 * i + 1] = xy[2 * (n - 1 - i) + 1];
        }
        return r;
    }

    private static String label(ShapeSpec spec) {
        return spec.name() != null ? spec.name() : "at " + spec.path();
    }

    private void body(BodySpec spec) {
        BodyState s = spec.state();
        if (s.kinematic()) {
            throw new Skip("a kinematic body (the original has static and dynamic bodies only)");
        }
        if (!s.defaultFilter()) {
            throw new Skip("categories, mask or group (the original has layers only)");
        }
        if (s.sensor()) {
            throw new Skip("a sensor body (the original's sensors are events, not bodies)");
        }
        PhyBody b = new PhyBody();
        b.setShapeIndex(shape(spec.shape()));
        b.setPosition(vec(spec.x(), spec.y()));
        b.setVelocity(vec(s.vx(), s.vy()));
        double turn = 2 * Math.PI;
        b.setAngleRaw(fx2(s.angle() - Math.floor(s.angle() / turn) * turn));
        b.setAngularVelocityRaw(fx2(-s.angularVelocity()));
        b.setFlags((s.isStatic() ? 0 : PhyBody.FLAG_DYNAMIC) | (s.rotatable() ? PhyBody.FLAG_ROTATES : 0)
                | (s.interacting() ? 0 : PhyBody.FLAG_NOT_INTERACTING) | (s.gravity() ? 0 : PhyBody.FLAG_NO_GRAVITY));
        int layers = 0;
        for (int layer : s.layers()) {
            layers |= 1 << layer;
        }
        b.setCollisionLayers(layers);
        if (!s.sleepingAllowed()) {
            notConverted.add("body " + spec.name() + ": sleepingAllowed false (the original engine has no sleeping)");
        }
        b.setUserData(NAME_KEY + spec.name());
        bodies.put(spec.name(), doc.getBodies().size());
        doc.getBodies().add(b);
    }

    private void element(String key, JsonNode node) {
        switch (key) {
            case "joints" -> each(node, "joint", n -> joint(n));
            case "springs" -> each(node, "spring", n -> spring(n));
            case "motors" -> each(node, "motor", n -> motor(n));
            case "landscape" -> attempt("landscape", () -> landscape(node));
            case "particles" -> each(node, "particle emitter", n -> emitter(n));
            default -> notConverted.add(key + " (a world file stores no " + key + ")");
        }
    }

    private interface NodeConsumer {
        void accept(JsonNode n);
    }

    private void each(JsonNode list, String what, NodeConsumer c) {
        for (int i = 0; i < list.size(); i++) {
            JsonNode n = list.get(i);
            attempt(what + " " + i, () -> c.accept(n));
        }
    }

    private int bodyIndex(JsonNode n, String key) {
        Integer i = bodies.get(n.get(key).asText());
        if (i == null) {
            throw new Skip("its body " + n.get(key).asText() + " is not converted");
        }
        if (i >= PhyWorld.NONE) {
            throw new Skip("its body is number " + i + "; a reference holds 0 to 254");
        }
        return i;
    }

    /** A body-local anchor: the given one, or the world point {@code at} seen from the body. */
    private double[] anchor(JsonNode n, String key, BodySpec b) {
        if (n.has("at")) {
            double c = Math.cos(b.state().angle());
            double s = Math.sin(b.state().angle());
            double wx = n.get("at").get(0).asDouble() - b.x();
            double wy = n.get("at").get(1).asDouble() - b.y();
            return new double[] {c * wx + s * wy, -s * wx + c * wy};
        }
        return n.has(key) ? new double[] {n.get(key).get(0).asDouble(), n.get(key).get(1).asDouble()}
                : new double[] {0, 0};
    }

    private double[] pair(JsonNode n, PhyPairConstraint c) {
        BodySpec sa = scene.body(n.get("bodyA").asText());
        BodySpec sb = scene.body(n.get("bodyB").asText());
        double[] pa = anchor(n, "anchorA", sa);
        double[] pb = anchor(n, "anchorB", sb);
        c.setBody1(bodyIndex(n, "bodyA"));
        c.setAnchor1(vec(pa[0], pa[1]));
        c.setBody2(bodyIndex(n, "bodyB"));
        c.setAnchor2(vec(pb[0], pb[1]));
        double ca = Math.cos(sa.state().angle());
        double sna = Math.sin(sa.state().angle());
        double cb = Math.cos(sb.state().angle());
        double snb = Math.sin(sb.state().angle());
        double dx = sb.x() + cb * pb[0] - snb * pb[1] - (sa.x() + ca * pa[0] - sna * pa[1]);
        double dy = sb.y() + snb * pb[0] + cb * pb[1] - (sa.y() + sna * pa[0] + ca * pa[1]);
        return new double[] {dx, dy};
    }

    private void joint(JsonNode n) {
        String type = n.path("type").asText("pin");
        if (!type.equals("pin")) {
            throw new Skip("type " + type + " (a world file holds only the manual's pin and fixed joints)");
        }
        PhyJoint j = new PhyJoint();
        for (String key : new String[] {"stiffness", "breakForce"}) {
            if (n.has(key)) {
                approximated.add("joint " + doc.getConstraints().size() + ": " + key
                        + " is not stored (the original's joints are rigid and unbreakable)");
            }
        }
        pair(n, j);
        j.setFixedByte(n.path("fixed").asBoolean(false) ? 1 : 0);
        if (!n.path("collide").asBoolean(false)) {
            approximated.add("joint " + doc.getConstraints().size() + ": collide false is not stored (the original "
                    + "keeps jointed bodies apart only through a shared layer)");
        }
        doc.getConstraints().add(j);
    }

    private void spring(JsonNode n) {
        PhySpring s = new PhySpring();
        double[] d = pair(n, s);
        s.setRestLengthRaw(fx(n.has("restLength") ? n.get("restLength").asDouble() : Math.hypot(d[0], d[1])));
        s.setCoefficientRaw(fx(n.path("stiffness").asDouble(0)));
        if (n.path("damping").asDouble(0) != 0) {
            approximated.add("spring " + doc.getConstraints().size() + ": damping "
                    + YamlText.num(n.get("damping").asDouble()) + " is not stored (the original's springs have none)");
        }
        if (!n.path("collide").asBoolean(true)) {
            approximated.add("spring " + doc.getConstraints().size() + ": collide false is not stored");
        }
        doc.getConstraints().add(s);
    }

    private void motor(JsonNode n) {
        PhyMotor m = new PhyMotor();
        m.setBody(bodyIndex(n, "body"));
        if (n.has("angularVelocity")) {
            m.setFlags(PhyMotor.FLAG_ROTATIONAL);
            m.setTargetARaw(fx2(-n.get("angularVelocity").asDouble()));
        } else {
            m.setTargetARaw(fx(n.get("velocity").get(0).asDouble()));
            m.setTargetBRaw(fx(n.get("velocity").get(1).asDouble()));
        }
        m.setMaxForceRaw(fx(n.get("maxImpulse").asDouble()));
        doc.getConstraints().add(m);
    }

    private void landscape(JsonNode n) {
        PhyLandscape l = new PhyLandscape();
        l.getMaterial().setFrictionRaw(fx(n.path("friction").asDouble(0.25)));
        l.getMaterial().setElasticityRaw(fx(n.path("elasticity").asDouble(0)));
        JsonNode segments = n.get("segments");
        for (int i = 0; i < segments.size(); i++) {
            JsonNode s = segments.get(i);
            String face = s.path("face").asText("none");
            l.getSegments().add(new PhySegment(vec(s.get("from").get(0).asDouble(), s.get("from").get(1).asDouble()),
                    vec(s.get("to").get(0).asDouble(), s.get("to").get(1).asDouble()),
                    face.equals("left") ? PhySegment.FACE_LEFT : face.equals("right") ? PhySegment.FACE_RIGHT
                            : PhySegment.FACE_NONE));
        }
        doc.setLandscape(l);
    }

    private void emitter(JsonNode n) {
        PhyParticleEmitter p = new PhyParticleEmitter();
        p.setBody(n.has("body") ? bodyIndex(n, "body") : PhyWorld.NONE);
        JsonNode from = n.get("from");
        JsonNode to = n.has("to") ? n.get("to") : from;
        p.setPosition1(vec(from.get(0).asDouble(), from.get(1).asDouble()));
        p.setPosition2(vec(to.get(0).asDouble(), to.get(1).asDouble()));
        p.setMaxParticles(n.path("maxCount").asInt(100));
        p.setRateRaw(fx(n.path("rate").asDouble(20)));
        p.setRateSpreadRaw(fx(n.path("rateSpread").asDouble(0)));
        p.setLifetimeRaw(fx(n.path("lifetime").asDouble(2)));
        p.setLifetimeSpreadRaw(fx(n.path("lifetimeSpread").asDouble(0)));
        p.setSpeedRaw(fx(n.path("speed").asDouble(10)));
        p.setSpeedSpreadRaw(fx(n.path("speedSpread").asDouble(0)));
        p.setEmitAngleRaw(fx2(Math.toRadians(n.path("angleDeg").asDouble(0))));
        p.setEmitAngleSpreadRaw(fx2(Math.toRadians(n.path("angleSpreadDeg").asDouble(0))));
        p.setAxesFixedByte(n.path("axesFixed").asBoolean(false) ? 1 : 0);
        p.setElasticityRaw(fx(n.path("elasticity").asDouble(1)));
        p.setGravityFactorRaw(fx(n.path("gravityFactor").asDouble(1)));
        p.setDampingRaw(fx(n.path("damping").asDouble(0)));
        String label = "particle emitter " + doc.getParticleEmitters().size();
        if (n.has("seed")) {
            approximated.add(label + ": the seed is not stored (the original draws from its own random source)");
        }
        if (!n.path("collide").asBoolean(true)) {
            approximated.add(label + ": collide false is not stored (particles always collide in a loaded world)");
        }
        doc.getParticleEmitters().add(p);
    }

    private static PhyVector vec(double x, double y) {
        return new PhyVector(fx(x), fx(y));
    }

    /** The nearest FX value; a value outside the FX range cannot be stored. */
    static int fx(double v) {
        return raw(v, PhyFixed.FX_ONE, "FX (|v| < 524288)");
    }

    /** The nearest 2FX value. */
    static int fx2(double v) {
        return raw(v, PhyFixed.FX2_ONE, "2FX (|v| < 128)");
    }

    private static int raw(double v, int one, String range) {
        double r = Math.rint(v * one);
        if (!(r >= Integer.MIN_VALUE && r <= Integer.MAX_VALUE)) {
            throw new Skip("value " + v + " is outside the range of " + range);
        }
        return (int) r;
    }
}
