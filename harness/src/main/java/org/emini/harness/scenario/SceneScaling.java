package org.emini.harness.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A scene with every length multiplied by a factor k (the harness's {@code run --scale}), and the
 * engine's length scale multiplied by k too: the same physics at another size, which must reach the
 * same outcomes, each bound scaled by its unit. Time is not scaled and mass is a ratio, so a quantity
 * of length<sup>p</sup> scales by k<sup>p</sup>: positions, sizes, speeds, gravity, impulses and forces
 * by k, energy, torque and angular momentum by k², angles, counts and relative figures not at all.
 *
 * <p>Covers what the stacking, fast-body and closed-form scenes use: shapes, bodies, actions, the
 * landscape, metrics, expectations and the closed-form models' lengths. Joints, springs, motors,
 * particles and the simulation area carry lengths in shapes of their own; a scene with one is refused
 * ({@link IllegalArgumentException} naming it) rather than scaled halfway.
 */
public final class SceneScaling {
    private SceneScaling() {
    }

    /** Elements this scaling does not cover. */
    private static final Set<String> UNSCALED_ELEMENTS = Set.of("joints", "springs", "motors", "particles",
            "simulationArea");
    /** Keys of the closed-form models whose values are lengths (px or [px, px]). */
    private static final Set<String> CLOSED_FORM_LENGTHS = Set.of("restY", "radius", "pivot", "anchor",
            "restLength");

    /**
     * The scene at k times its size.
     *
     * @param s the scene
     * @param k the factor, finite and &gt; 0
     * @return the scaled scene, named as the original
     * @throws IllegalArgumentException when the scene has an element this scaling does not cover
     */
    public static Scenario scale(Scenario s, double k) {
        if (!(k > 0) || Double.isInfinite(k)) {
            throw new IllegalArgumentException("scale must be finite and > 0, was " + k);
        }
        for (String key : s.elements().keySet()) {
            if (UNSCALED_ELEMENTS.contains(key)) {
                throw new IllegalArgumentException("cannot scale a scene with " + key
                        + " (scaling covers shapes, bodies, actions, landscape, metrics and expectations)");
            }
        }
        Map<ShapeSpec, ShapeSpec> scaledShapes = new IdentityHashMap<>();
        Map<String, ShapeSpec> shapes = new LinkedHashMap<>();
        s.shapes().forEach((name, shape) -> shapes.put(name, shape(shape, k, scaledShapes)));
        List<BodySpec> bodies = new ArrayList<>();
        for (BodySpec b : s.bodies()) {
            bodies.add(new BodySpec(b.name(), shape(b.shape(), k, scaledShapes), b.x() * k, b.y() * k,
                    state(b.state(), k), b.path()));
        }
        List<ActionSpec> actions = new ArrayList<>();
        for (ActionSpec a : s.actions()) {
            actions.add(action(a, k));
        }
        Map<String, Section> elements = new LinkedHashMap<>();
        s.elements().forEach((key, section) -> elements.put(key,
                key.equals("landscape") ? landscape(section, k) : section));
        return new Scenario(s.name(), s.file(), s.description(), s.category(), world(s.world(), k), shapes, bodies,
                actions, elements, run(s.run(), k), closedForm(s.closedForm(), k), s.oracle(), s.knownFailure());
    }

    /**
     * The power of length in a channel's unit: 1 for px, px/s and momentum, 2 for energy and angular
     * momentum, 0 for angles, counts and fractions.
     *
     * @param channel a metric or body channel
     * @return the power
     * @throws IllegalArgumentException for a channel this scaling does not know
     */
    public static int lengthPower(String pairOrChannel) {
        String channel = Channels.base(pairOrChannel);
        String[] body = Channels.bodyChannel(channel);
        if (body != null) {
            return body[1].equals("angle") || body[1].equals("omega") || body[1].equals("turn") ? 0 : 1;
        }
        switch (channel) {
            case "energy.kinetic":
            case "energy.potential":
            case "energy.total":
            case "angularMomentum":
                return 2;
            case "momentum.x":
            case "momentum.y":
            case "penetration.max":
            case "penetration.mean":
            case "constraintError.max":
            case "constraintError.mean":
            case "jointLimits.translation":
            case "stability.maxSpeed":
                return 1;
            case "penetration.points":
            case "tunnelling.count":
            case "jointLimits.angle":
            case "stability.maxAngularSpeed":
            case "stability.nonFinite":
            case "particles.count":
            case "particles.outside":
            case "sleeping.count":
            case "sleeping.fraction":
                return 0;
            default:
                throw new IllegalArgumentException("cannot scale channel " + channel);
        }
    }

    private static WorldSpec world(WorldSpec w, double k) {
        Map<String, Double> solver = new LinkedHashMap<>(w.solver());
        solver.merge("lengthScale", k, (was, factor) -> was * factor);
        SleepSpec sl = w.sleeping();
        SleepSpec sleeping = new SleepSpec(sl.enabled(), sl.linearTolerance() * k, sl.angularTolerance(),
                sl.timeToSleep());
        return new WorldSpec(w.timestep(), w.iterations(), w.dynamicIterations(), w.gravityX() * k, w.gravityY() * k,
                w.dampingLateral(), w.dampingRotational(), w.hasSimulationArea(), solver, sleeping);
    }

    private static ShapeSpec shape(ShapeSpec s, double k, Map<ShapeSpec, ShapeSpec> done) {
        ShapeSpec known = done.get(s);
        if (known != null) {
            return known;
        }
        List<double[]> vertices = null;
        if (s.vertices() != null) {
            vertices = new ArrayList<>();
            for (double[] v : s.vertices()) {
                vertices.add(times(v, k));
            }
        }
        List<ShapeSpec.Part> parts = null;
        if (s.parts() != null) {
            parts = new ArrayList<>();
            for (ShapeSpec.Part p : s.parts()) {
                parts.add(new ShapeSpec.Part(shape(p.shape(), k, done), p.offsetX() * k, p.offsetY() * k, p.angle()));
            }
        }
        ShapeSpec out = new ShapeSpec(s.name(), s.kind(), s.radius() * k, s.width() * k, s.height() * k, s.sides(),
                vertices, parts, s.mass(), s.friction(), s.elasticity(), s.path());
        done.put(s, out);
        return out;
    }

    private static BodyState state(BodyState b, double k) {
        return new BodyState(b.isStatic(), b.kinematic(), b.angle(), b.vx() * k, b.vy() * k, b.angularVelocity(),
                b.rotatable(), b.interacting(), b.gravity(), b.layers(), b.categoryBits(), b.maskBits(), b.group(),
                b.sleepingAllowed(), b.sensor());
    }

    private static ActionSpec action(ActionSpec a, double k) {
        // Angular impulse and torque are force times length; an angular velocity and a count are not lengths.
        double value = a.kind() == ActionSpec.Kind.angularImpulse || a.kind() == ActionSpec.Kind.torque
                ? a.value() * k * k : a.value();
        return new ActionSpec(a.at(), a.kind(), a.body(), times(a.vector(), k), times(a.point(), k), value,
                a.duration(), a.emitter(), a.path());
    }

    private static RunSpec run(RunSpec r, double k) {
        List<MetricSpec> metrics = new ArrayList<>();
        for (MetricSpec m : r.record().metrics()) {
            List<MetricSpec.WallSpec> walls = new ArrayList<>();
            for (MetricSpec.WallSpec w : m.walls()) {
                walls.add(new MetricSpec.WallSpec(w.body(), times(w.from(), k), times(w.to(), k)));
            }
            metrics.add(new MetricSpec(m.kind(), m.aboutX() * k, m.aboutY() * k, walls, m.bodies(), m.emitters(),
                    times(m.regionMin(), k), times(m.regionMax(), k), m.path(), m.wholeShape(), m.pairs()));
        }
        RecordSpec rec = r.record();
        List<ExpectationSpec> expect = new ArrayList<>();
        for (ExpectationSpec e : r.expect()) {
            expect.add(expectation(e, k));
        }
        return new RunSpec(r.duration(), new RecordSpec(rec.every(), metrics, rec.bodies(), rec.bodyNames(),
                rec.trace()), expect);
    }

    private static ExpectationSpec expectation(ExpectationSpec e, double k) {
        double f;
        switch (e.kind()) {
            case METRIC:
            case CLOSED_FORM:
                // Times (firstCrossing, period) do not scale; the value crossed does, as the channel.
                f = e.relative() || isTime(e.of()) || e.relativeTo() != null ? 1 : Math.pow(k, lengthPower(e.channel()));
                break;
            case ENDS_NEAR:
            case STAYS_INSIDE:
                f = k;
                break;
            default:
                f = 1;
                break;
        }
        return new ExpectationSpec(e.kind(), e.channel(), e.of(), e.at(), e.relative(), e.body(), times(e.point(), k),
                times(e.max(), k), e.atMost() * f, e.atLeast() * f, e.near() * f, e.tolerance() * f, e.windowFrom(),
                e.windowUntil(), e.maxSpeed() * k, e.maxAngularSpeed(), e.maxEnergyRise() * k * k, e.name(), e.why(),
                e.knownFailure(), e.path(), e.crossing() * (e.channel() == null ? 1 : Math.pow(k, lengthPower(e.channel()))),
                e.inOrder(), e.minus(), e.relativeTo(), e.minusTrace() == null ? null
                        : e.minusTrace().times(Math.pow(k, lengthPower(e.minusTrace().channel()))));
    }

    private static boolean isTime(String of) {
        return "firstCrossing".equals(of) || "period".equals(of);
    }

    private static Section landscape(Section s, double k) {
        ObjectNode node = s.node().deepCopy();
        for (JsonNode segment : node.withArray("segments")) {
            scaleVector((ObjectNode) segment, "from", k);
            scaleVector((ObjectNode) segment, "to", k);
        }
        return new Section(node, s.path());
    }

    private static Section closedForm(Section s, double k) {
        if (s == null) {
            return null;
        }
        ObjectNode node = s.node().deepCopy();
        for (String key : CLOSED_FORM_LENGTHS) {
            JsonNode v = node.get(key);
            if (v == null) {
                continue;
            }
            if (v.isArray()) {
                scaleVector(node, key, k);
            } else {
                node.put(key, v.asDouble() * k);
            }
        }
        return new Section(node, s.path());
    }

    private static void scaleVector(ObjectNode parent, String key, double k) {
        ArrayNode v = (ArrayNode) parent.get(key);
        for (int i = 0; i < v.size(); i++) {
            v.set(i, v.get(i).asDouble() * k);
        }
    }

    private static double[] times(double[] v, double k) {
        if (v == null) {
            return null;
        }
        double[] out = new double[v.length];
        for (int i = 0; i < v.length; i++) {
            out[i] = v[i] * k;
        }
        return out;
    }
}
