package org.emini.harness.load;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.emini.harness.generate.Generators;
import org.emini.harness.scenario.ActionSpec;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.BodyState;
import org.emini.harness.scenario.Channels;
import org.emini.harness.scenario.ElementNames;
import org.emini.harness.scenario.ExpectationSpec;
import org.emini.harness.scenario.GeneratorSpec;
import org.emini.harness.scenario.KnownFailure;
import org.emini.harness.scenario.MetricSpec;
import org.emini.harness.scenario.RecordSpec;
import org.emini.harness.scenario.ReferenceTrace;
import org.emini.harness.scenario.RunSpec;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.Section;
import org.emini.harness.scenario.ShapeSpec;
import org.emini.harness.scenario.SleepSpec;
import org.emini.harness.scenario.WorldSpec;

/**
 * Turns a schema-valid document into a {@link Scenario}: fills in the manual's defaults, resolves shape
 * and body names, expands generators and checks what a schema cannot (mutually exclusive keys, names
 * that must exist, channels that must be known). Every problem is located through the source map.
 */
final class ScenarioReader {
    /** Top-level elements kept as written and built by their own builders. */
    static final List<String> ELEMENT_SECTIONS = List.of("joints", "springs", "motors", "landscape", "particles");

    private final String file;
    private final SourceMap sourceMap;
    private final List<Problem> problems = new ArrayList<>();
    private final Map<String, ShapeSpec> shapes = new LinkedHashMap<>();
    /** Convex parts of each shape read so far (1 for a circle or polygon). */
    private final Map<ShapeSpec, Long> convexParts = new java.util.IdentityHashMap<>();
    /** The generators' names: a bare one in an expectation stands for its bodies ({@code NAME[*]}). */
    private final Set<String> generators = new LinkedHashSet<>();
    /** The penetration pair filters the expectations read ({@code between}), in order. */
    private final Set<MetricSpec.PairSpec> pairFilters = new LinkedHashSet<>();
    /** Whether the scene has a landscape (a party of penetration pairs). */
    private boolean hasLandscape;

    ScenarioReader(String file, SourceMap sourceMap) {
        this.file = file;
        this.sourceMap = sourceMap;
    }

    List<Problem> problems() {
        return problems;
    }

    /** Reads the scene; returns null when there are problems. */
    Scenario read(JsonNode root, String defaultName) {
        JsonPath r = JsonPath.ROOT;
        String name = root.has("name") ? root.get("name").asText() : defaultName;
        WorldSpec world = world(root.get("world"), r.key("world"));
        JsonNode shapesNode = root.get("shapes");
        if (shapesNode != null) {
            shapesNode.fields().forEachRemaining(e -> {
                JsonPath p = r.key("shapes").key(e.getKey());
                shapes.put(e.getKey(), shape(e.getKey(), e.getValue(), p));
            });
        }
        List<BodySpec> bodies = new ArrayList<>();
        JsonNode bodiesNode = root.get("bodies");
        if (bodiesNode != null) {
            for (int i = 0; i < bodiesNode.size(); i++) {
                JsonNode b = bodiesNode.get(i);
                JsonPath p = r.key("bodies").index(i);
                ShapeSpec shape = shapeRef(b.get("shape"), p.key("shape"));
                double[] pos = vec(b.get("position"), 0, 0);
                String bodyName = b.has("name") ? b.get("name").asText() : "body" + i;
                bodies.add(new BodySpec(bodyName, shape, pos[0], pos[1], state(b, p), p));
            }
        }
        JsonNode generators = root.get("generators");
        if (generators != null) {
            for (int i = 0; i < generators.size(); i++) {
                GeneratorSpec g = generator(generators.get(i), r.key("generators").index(i));
                if (g == null) {
                    continue;
                }
                this.generators.add(g.name());
                // Counted before expanding, so that a generator of 10^10 bodies is refused, not attempted.
                long made = Generators.size(g);
                if (bodies.size() + made > Limits.BODIES) {
                    problem(g.path(), "this generator makes " + made + " bodies; with the " + bodies.size()
                            + " before it the scene would hold more than the " + Limits.BODIES + " a scene may have");
                    break;
                }
                bodies.addAll(Generators.expand(g));
            }
        }
        Set<String> names = new HashSet<>();
        for (BodySpec b : bodies) {
            if (!names.add(b.name())) {
                problem(b.path(), "duplicate body name '" + b.name() + "'");
            }
        }
        hasLandscape = root.has("landscape");
        Map<String, Section> elements = new LinkedHashMap<>();
        for (String section : ELEMENT_SECTIONS) {
            if (root.has(section)) {
                elements.put(section, new Section(root.get(section), r.key(section)));
                checkBodyRefs(root.get(section), r.key(section), names);
            }
        }
        Set<String> emitters = new LinkedHashSet<>();
        JsonNode particles = root.get("particles");
        if (particles != null) {
            for (int i = 0; i < particles.size(); i++) {
                if (!emitters.add(ElementNames.emitter(particles.get(i), i))) {
                    problem(r.key("particles").index(i), "duplicate emitter name '"
                            + ElementNames.emitter(particles.get(i), i) + "'");
                }
            }
        }
        List<ActionSpec> actions = actions(root.get("actions"), r.key("actions"), names, emitters);
        staticVelocities(actions, bodies);
        JsonNode worldNode = root.get("world");
        if (worldNode != null && worldNode.has("simulationArea")) {
            elements.put("world.simulationArea", new Section(worldNode.get("simulationArea"),
                    r.key("world").key("simulationArea")));
        }
        Section closedForm = null;
        Section oracle = null;
        JsonNode reference = root.get("reference");
        if (reference != null) {
            if (reference.has("closedForm")) {
                closedForm = new Section(reference.get("closedForm"), r.key("reference").key("closedForm"));
                checkBodyRefs(reference.get("closedForm"), closedForm.path(), names);
            }
            if (reference.has("oracle")) {
                oracle = new Section(reference.get("oracle"), r.key("reference").key("oracle"));
            }
        }
        RunSpec run = run(root.get("run"), r.key("run"), names, emitters, closedForm != null);
        KnownFailure known = knownFailure(root.get("knownFailure"));
        String description = root.has("description") ? root.get("description").asText() : "";
        String category = root.has("category") ? root.get("category").asText() : null;
        if (!problems.isEmpty()) {
            return null;
        }
        Scenario scenario = new Scenario(name, file, description, category, world, shapes, bodies, actions, elements,
                run, closedForm, oracle, known);
        for (Budget.Excess e : Budget.check(scenario)) {
            problem(e.path(), e.message());
        }
        for (ExpectationSpec e : run.expect()) {
            String mismatch = e.minusTrace() == null ? null
                    : e.minusTrace().mismatch(world.timestep(), ReferenceTraces.sampleTicks(scenario));
            if (mismatch != null) {
                problem(e.path().key("minus").key("trace"), mismatch);
            }
        }
        return problems.isEmpty() ? scenario : null;
    }

    private WorldSpec world(JsonNode w, JsonPath p) {
        WorldSpec d = WorldSpec.DEFAULT;
        if (w == null) {
            return d;
        }
        if (w.has("ticksPerSecond") && w.has("timestep")) {
            problem(p.key("timestep"), "give ticksPerSecond or timestep, not both");
        }
        JsonNode area = w.get("simulationArea");
        if (area != null && area.has("end") && area.get("end").asDouble() < area.get("start").asDouble()) {
            problem(p.key("simulationArea").key("end"), "the simulation area ends before it starts");
        }
        if (area != null && area.has("max") && (area.get("max").get(0).asDouble() < area.get("min").get(0).asDouble()
                || area.get("max").get(1).asDouble() < area.get("min").get(1).asDouble())) {
            problem(p.key("simulationArea").key("max"), "the simulation area's max is below its min");
        }
        double timestep = w.has("timestep") ? w.get("timestep").asDouble()
                : w.has("ticksPerSecond") ? 1.0 / w.get("ticksPerSecond").asDouble() : d.timestep();
        double[] g = vec(w.get("gravity"), d.gravityX(), d.gravityY());
        JsonNode damping = w.get("damping");
        Map<String, Double> solver = new LinkedHashMap<>();
        if (w.has("solver")) {
            w.get("solver").fields().forEachRemaining(e -> solver.put(e.getKey(), e.getValue().asDouble()));
        }
        return new WorldSpec(timestep,
                w.has("iterations") ? w.get("iterations").asInt() : d.iterations(),
                w.has("dynamicIterations") ? w.get("dynamicIterations").asBoolean() : d.dynamicIterations(),
                g[0], g[1],
                damping != null && damping.has("lateral") ? damping.get("lateral").asDouble() : d.dampingLateral(),
                damping != null && damping.has("rotational") ? damping.get("rotational").asDouble()
                        : d.dampingRotational(),
                w.has("simulationArea"), solver, sleeping(w.get("sleeping")));
    }

    /** {@code sleeping: true|false} or an object of tolerances (which turns it on). */
    private static SleepSpec sleeping(JsonNode s) {
        if (s == null) {
            return SleepSpec.OFF;
        }
        if (s.isBoolean()) {
            return SleepSpec.OFF.switched(s.asBoolean());
        }
        return new SleepSpec(true, num(s, "linearTolerance", Double.NaN), num(s, "angularTolerance", Double.NaN),
                num(s, "timeToSleep", Double.NaN));
    }

    private ShapeSpec shapeRef(JsonNode node, JsonPath p) {
        if (node.isTextual()) {
            ShapeSpec s = shapes.get(node.asText());
            if (s == null) {
                problem(p, "no shape named '" + node.asText() + "' under shapes" + known(shapes.keySet()));
            }
            return s;
        }
        return shape(null, node, p);
    }

    private ShapeSpec shape(String name, JsonNode s, JsonPath p) {
        ShapeSpec.Kind kind = ShapeSpec.Kind.valueOf(s.get("type").asText());
        List<double[]> vertices = new ArrayList<>();
        if (s.has("vertices")) {
            for (JsonNode v : s.get("vertices")) {
                vertices.add(vec(v, 0, 0));
            }
        }
        List<ShapeSpec.Part> parts = new ArrayList<>();
        if (s.has("parts")) {
            for (int i = 0; i < s.get("parts").size(); i++) {
                JsonNode part = s.get("parts").get(i);
                double[] off = vec(part.get("offset"), 0, 0);
                parts.add(new ShapeSpec.Part(shapeRef(part.get("shape"), p.key("parts").index(i).key("shape")),
                        off[0], off[1], num(part, "angle", 0)));
            }
        }
        double defaultMass = 1;
        long leaves = 1;
        if (kind == ShapeSpec.Kind.multiShape) {
            defaultMass = 0;
            leaves = 0;
            for (ShapeSpec.Part part : parts) {
                defaultMass += part.shape() == null ? 0 : part.shape().mass();
                leaves += part.shape() == null ? 0 : convexParts.getOrDefault(part.shape(), 1L);
            }
            // Named multi-shapes nest by reference: ten levels of three parts are 59,049 parts.
            if (leaves > Limits.SHAPE_PARTS) {
                problem(p.key("parts"), "this multi-shape has " + leaves + " convex parts once its named parts are "
                        + "placed, more than the " + Limits.SHAPE_PARTS + " a shape may have");
                leaves = Limits.SHAPE_PARTS;
            }
        }
        ShapeSpec spec = new ShapeSpec(name, kind, num(s, "radius", 0), num(s, "width", 0), num(s, "height", 0),
                s.has("sides") ? s.get("sides").asInt() : 0, vertices, parts, num(s, "mass", defaultMass),
                num(s, "friction", 0.25), num(s, "elasticity", 0), p);
        convexParts.put(spec, leaves);
        return spec;
    }

    private BodyState state(JsonNode b, JsonPath p) {
        if (b == null) {
            return BodyState.DEFAULT;
        }
        if (b.has("angle") && b.has("angleDeg")) {
            problem(p.key("angleDeg"), "give angle or angleDeg, not both");
        }
        double angle = b.has("angleDeg") ? Math.toRadians(b.get("angleDeg").asDouble()) : num(b, "angle", 0);
        double[] v = vec(b.get("velocity"), 0, 0);
        List<Integer> layers = new ArrayList<>();
        if (b.has("layers")) {
            b.get("layers").forEach(l -> layers.add(l.asInt()));
        }
        boolean isStatic = bool(b, "static", false);
        boolean kinematic = bool(b, "kinematic", false);
        double omega = num(b, "angularVelocity", 0);
        if (isStatic && kinematic) {
            problem(p.key("kinematic"), "a body is static or kinematic, not both");
        } else if (isStatic && (v[0] != 0 || v[1] != 0)) {
            problem(p.key("velocity"), "a static body does not move; give kinematic: true to move it by its velocity");
        } else if (isStatic && omega != 0) {
            problem(p.key("angularVelocity"), "a static body does not turn; give kinematic: true to turn it");
        }
        return new BodyState(isStatic, kinematic, angle, v[0], v[1], omega,
                bool(b, "rotatable", true), bool(b, "interacting", true), bool(b, "gravity", true),
                List.copyOf(layers), bits(b, "categories", BodyState.DEFAULT_CATEGORY_BITS),
                bits(b, "mask", BodyState.DEFAULT_MASK_BITS), b.has("group") ? b.get("group").asInt() : 0,
                bool(b, "sleepingAllowed", true), bool(b, "sensor", false));
    }

    /** A list of bit numbers (0..31) as a bit set, or the default when absent. */
    private static int bits(JsonNode b, String key, int absent) {
        if (!b.has(key)) {
            return absent;
        }
        int bits = 0;
        for (JsonNode k : b.get(key)) {
            bits |= 1 << k.asInt();
        }
        return bits;
    }

    private GeneratorSpec generator(JsonNode g, JsonPath p) {
        GeneratorSpec.Kind kind = GeneratorSpec.Kind.valueOf(g.get("type").asText());
        List<ShapeSpec> list = new ArrayList<>();
        if (g.has("shape")) {
            list.add(shapeRef(g.get("shape"), p.key("shape")));
        }
        if (g.has("shapes")) {
            for (int i = 0; i < g.get("shapes").size(); i++) {
                list.add(shapeRef(g.get("shapes").get(i), p.key("shapes").index(i)));
            }
        }
        if (list.contains(null)) {
            return null;
        }
        double[] spacing = null;
        if (g.has("spacing")) {
            JsonNode s = g.get("spacing");
            spacing = s.isNumber() ? new double[] {s.asDouble()} : vec(s, 0, 0);
        } else if (kind != GeneratorSpec.Kind.rain && list.get(0).size() == null) {
            problem(p, "give spacing: the default spacing needs a shape with a known size");
            return null;
        }
        JsonNode anchor = g.has("base") ? g.get("base") : g.has("origin") ? g.get("origin") : g.get("start");
        JsonNode region = g.get("region");
        return new GeneratorSpec(kind, g.get("name").asText(), list, vec(anchor, 0, 0),
                g.has("count") ? g.get("count").asInt() : 0, g.has("rows") ? g.get("rows").asInt() : 0,
                g.has("columns") ? g.get("columns").asInt() : 0, spacing,
                region != null ? vec(region.get("min"), 0, 0) : null,
                region != null ? vec(region.get("max"), 0, 0) : null,
                g.has("seed") ? g.get("seed").asLong() : 0, bool(g, "randomAngle", false),
                state(g.get("body"), p.key("body")), p);
    }

    /** A velocity action that would move a static body: the engine refuses it, so the scene is refused. */
    private void staticVelocities(List<ActionSpec> actions, List<BodySpec> bodies) {
        Set<String> still = new HashSet<>();
        for (BodySpec b : bodies) {
            if (b.state().isStatic()) {
                still.add(b.name());
            }
        }
        for (ActionSpec a : actions) {
            boolean moves = a.vector() != null && (a.vector()[0] != 0 || a.vector()[1] != 0)
                    || !Double.isNaN(a.value()) && a.value() != 0;
            if (a.kind() == ActionSpec.Kind.velocity && moves && still.contains(a.body())) {
                problem(a.path(), "body '" + a.body() + "' is static: it does not move; give it kinematic: true to move"
                        + " it by a velocity");
            }
        }
    }

    private List<ActionSpec> actions(JsonNode list, JsonPath p, Set<String> names, Set<String> emitters) {
        List<ActionSpec> out = new ArrayList<>();
        if (list == null) {
            return out;
        }
        for (int i = 0; i < list.size(); i++) {
            JsonNode a = list.get(i);
            JsonPath ap = p.index(i);
            ActionSpec.Kind kind = ActionSpec.Kind.valueOf(a.get("type").asText());
            String body = a.has("body") ? a.get("body").asText() : null;
            if (body != null && !names.contains(body)) {
                problem(ap.key("body"), "no body named '" + body + "'");
            }
            double[] vector = null;
            double value = Double.NaN;
            switch (kind) {
                case impulse:
                    vector = vec(a.get("impulse"), 0, 0);
                    break;
                case force:
                    vector = vec(a.get("force"), 0, 0);
                    break;
                case gravity:
                    vector = vec(a.get("gravity"), 0, 0);
                    break;
                case velocity:
                    vector = a.has("velocity") ? vec(a.get("velocity"), 0, 0) : null;
                    value = num(a, "angularVelocity", Double.NaN);
                    if (vector == null && Double.isNaN(value)) {
                        problem(ap, "give velocity, angularVelocity or both");
                    }
                    break;
                case torque:
                    value = a.get("torque").asDouble();
                    break;
                case emit:
                    value = a.get("count").asInt();
                    if (!emitters.contains(a.get("emitter").asText())) {
                        problem(ap.key("emitter"), "no emitter named '" + a.get("emitter").asText() + "'"
                                + known(emitters));
                    }
                    break;
                default:
                    value = a.get("angularImpulse").asDouble();
                    break;
            }
            out.add(new ActionSpec(a.get("at").asDouble(), kind, body, vector,
                    a.has("point") ? vec(a.get("point"), 0, 0) : null, value, num(a, "duration", Double.NaN),
                    a.has("emitter") ? a.get("emitter").asText() : null, ap));
        }
        return out;
    }

    private RunSpec run(JsonNode run, JsonPath p, Set<String> names, Set<String> emitters, boolean hasClosedForm) {
        JsonNode rec = run.get("record");
        JsonPath rp = p.key("record");
        Map<MetricSpec.Kind, MetricSpec> metrics = new LinkedHashMap<>();
        String bodies = "all";
        List<String> bodyNames = new ArrayList<>();
        if (rec != null && rec.has("metrics")) {
            JsonNode list = rec.get("metrics");
            for (int i = 0; i < list.size(); i++) {
                MetricSpec m = metric(list.get(i), rp.key("metrics").index(i), names, emitters);
                if (metrics.put(m.kind(), m) != null) {
                    problem(m.path(), "metric '" + m.kind() + "' is listed twice");
                }
            }
        }
        if (rec != null && rec.has("bodies")) {
            JsonNode b = rec.get("bodies");
            if (b.isTextual()) {
                bodies = b.asText();
            } else {
                bodies = null;
                for (int i = 0; i < b.size(); i++) {
                    String n = b.get(i).asText();
                    if (!names.contains(n)) {
                        problem(rp.key("bodies").index(i), "no body named '" + n + "'");
                    }
                    bodyNames.add(n);
                }
            }
        }
        List<ExpectationSpec> expect = new ArrayList<>();
        JsonNode list = run.get("expect");
        if (list != null) {
            for (int i = 0; i < list.size(); i++) {
                ExpectationSpec e = expectation(list.get(i), p.key("expect").index(i), names, hasClosedForm);
                if (e == null) {
                    continue;
                }
                expect.add(e);
                // An expectation is a request: add the metrics it needs (without options).
                MetricSpec.Kind needed = neededMetric(e);
                if (needed == MetricSpec.Kind.tunnelling && !metrics.containsKey(needed)) {
                    problem(e.path(), "noTunnelling needs the tunnelling metric with its walls under run.record.metrics");
                } else if (needed != null && !metrics.containsKey(needed)) {
                    metrics.put(needed, MetricSpec.plain(needed, null));
                }
                if (e.kind() == ExpectationSpec.Kind.STABLE && !Double.isNaN(e.maxEnergyRise())
                        && !metrics.containsKey(MetricSpec.Kind.energy)) {
                    metrics.put(MetricSpec.Kind.energy, MetricSpec.plain(MetricSpec.Kind.energy, null));
                }
                // The channels minus and relativeTo read: their metrics computed, their bodies recorded.
                for (String extra : extraChannels(e)) {
                    MetricSpec.Kind k = Channels.metricOf(extra);
                    if (k != null && k != MetricSpec.Kind.tunnelling && !metrics.containsKey(k)) {
                        metrics.put(k, MetricSpec.plain(k, null));
                    }
                    String[] xc = Channels.bodyChannel(extra);
                    if (xc != null && bodies == null && !bodyNames.contains(xc[0])) {
                        bodyNames.add(xc[0]);
                    }
                }
                // A group's members are recorded by the runner, in the order the scene creates them.
                if (e.body() != null && bodies == null && !bodyNames.contains(e.body()) && e.group() == null) {
                    bodyNames.add(e.body());
                }
                String[] bc = e.channel() != null ? Channels.bodyChannel(e.channel()) : null;
                if (bc != null && bodies == null && !bodyNames.contains(bc[0]) && e.group() == null) {
                    bodyNames.add(bc[0]);
                }
            }
        }
        if (!pairFilters.isEmpty()) {
            metrics.put(MetricSpec.Kind.penetration, metrics.get(MetricSpec.Kind.penetration).withPairs(List.copyOf(pairFilters)));
        }
        if (metrics.containsKey(MetricSpec.Kind.particles) && emitters.isEmpty()) {
            MetricSpec m = metrics.get(MetricSpec.Kind.particles);
            problem(m.path() != null ? m.path() : p, "the particles metric needs emitters under particles");
        }
        double every = rec != null && rec.has("every") ? rec.get("every").asDouble() : Double.NaN;
        boolean trace = rec == null || bool(rec, "trace", true);
        RecordSpec record = new RecordSpec(every, List.copyOf(metrics.values()), bodies, bodyNames, trace);
        return new RunSpec(run.get("duration").asDouble(), record, expect);
    }

    private MetricSpec metric(JsonNode m, JsonPath p, Set<String> names, Set<String> emitterNames) {
        if (m.isTextual()) {
            return MetricSpec.plain(MetricSpec.Kind.valueOf(m.asText()), p);
        }
        String key = m.fieldNames().next();
        JsonNode o = m.get(key);
        JsonPath op = p.key(key);
        MetricSpec.Kind kind = MetricSpec.Kind.valueOf(key);
        double[] about = vec(o.get("about"), 0, 0);
        List<MetricSpec.WallSpec> walls = new ArrayList<>();
        List<String> bodies = new ArrayList<>();
        if (o.has("walls")) {
            for (int i = 0; i < o.get("walls").size(); i++) {
                JsonNode w = o.get("walls").get(i);
                if (w.isTextual()) {
                    if (!names.contains(w.asText())) {
                        problem(op.key("walls").index(i), "no body named '" + w.asText() + "'");
                    }
                    walls.add(new MetricSpec.WallSpec(w.asText(), null, null));
                } else {
                    walls.add(new MetricSpec.WallSpec(null, vec(w.get("from"), 0, 0), vec(w.get("to"), 0, 0)));
                }
            }
        }
        if (o.has("bodies")) {
            for (int i = 0; i < o.get("bodies").size(); i++) {
                String n = o.get("bodies").get(i).asText();
                if (!names.contains(n)) {
                    problem(op.key("bodies").index(i), "no body named '" + n + "'");
                }
                bodies.add(n);
            }
        }
        List<String> emitters = new ArrayList<>();
        if (o.has("emitters")) {
            for (int i = 0; i < o.get("emitters").size(); i++) {
                String n = o.get("emitters").get(i).asText();
                if (!emitterNames.contains(n)) {
                    problem(op.key("emitters").index(i), "no emitter named '" + n + "'" + known(emitterNames));
                }
                emitters.add(n);
            }
        }
        JsonNode region = o.get("region");
        double[] min = region != null ? vec(region.get("min"), 0, 0) : null;
        double[] max = region != null ? vec(region.get("max"), 0, 0) : null;
        if (region != null && (max[0] < min[0] || max[1] < min[1])) {
            problem(op.key("region"), "region max must not be below min");
        }
        return new MetricSpec(kind, about[0], about[1], walls, bodies, emitters, min, max, p,
                "shape".equals(o.path("points").asText("centre")), List.of());
    }

    private ExpectationSpec expectation(JsonNode e, JsonPath p, Set<String> names, boolean hasClosedForm) {
        return expectation(e, p, names, hasClosedForm, false);
    }

    /** An expectation; {@code figure}: the figure of a relativeTo, which has no bounds of its own. */
    private ExpectationSpec expectation(JsonNode e, JsonPath p, Set<String> names, boolean hasClosedForm, boolean figure) {
        List<String> kinds = new ArrayList<>();
        for (String k : List.of("metric", "closedForm", "endsNear", "staysInside", "noTunnelling", "stable")) {
            if (e.has(k)) {
                kinds.add(k);
            }
        }
        if (kinds.size() != 1) {
            problem(p, kinds.isEmpty()
                    ? "an expectation needs one of metric, closedForm, endsNear, staysInside, noTunnelling, stable"
                    : "an expectation checks one thing; found " + String.join(", ", kinds));
            return null;
        }
        String k = kinds.get(0);
        ExpectationSpec.Kind kind = switch (k) {
            case "metric" -> ExpectationSpec.Kind.METRIC;
            case "closedForm" -> ExpectationSpec.Kind.CLOSED_FORM;
            case "endsNear" -> ExpectationSpec.Kind.ENDS_NEAR;
            case "staysInside" -> ExpectationSpec.Kind.STAYS_INSIDE;
            case "noTunnelling" -> ExpectationSpec.Kind.NO_TUNNELLING;
            default -> ExpectationSpec.Kind.STABLE;
        };
        String channel = null;
        String minus = null;
        ReferenceTrace minusTrace = null;
        ExpectationSpec relativeTo = null;
        String of = e.has("of") ? e.get("of").asText() : null;
        double at = num(e, "at", Double.NaN);
        double atMost = num(e, "atMost", Double.NaN);
        double atLeast = num(e, "atLeast", Double.NaN);
        double near = num(e, "near", Double.NaN);
        double tolerance = num(e, "tolerance", Double.NaN);
        boolean bounded = !Double.isNaN(atMost) || !Double.isNaN(atLeast) || !Double.isNaN(near);
        if (!Double.isNaN(near) && Double.isNaN(tolerance)) {
            problem(p.key("near"), "near needs a tolerance");
        }
        String body = e.has("body") ? group(e.get("body").asText(), names, p.key("body")) : null;
        if (body != null && !known(body, names)) {
            problem(p.key("body"), Channels.isGroup(body) ? "'" + body + "' matches no body" : "no body named '" + body + "'");
        }
        double crossing = num(e, "crossing", Double.NaN);
        boolean inOrder = bool(e, "inOrder", false);
        if (kind == ExpectationSpec.Kind.METRIC || kind == ExpectationSpec.Kind.CLOSED_FORM) {
            channel = e.get(k).asText();
            JsonPath cp = p.key(k);
            String[] bc = Channels.bodyChannel(channel);
            if (bc != null) {
                bc[0] = group(bc[0], names, cp);
                channel = Channels.body(bc[0], bc[1]);
            }
            if (bc == null && Channels.metricOf(channel) == null) {
                problem(cp, "unknown channel '" + channel + "' (see scenarios/README.md, Metrics)");
            } else if (bc != null && !known(bc[0], names)) {
                problem(cp, Channels.isGroup(bc[0]) ? "'" + bc[0] + "' matches no body" : "no body named '" + bc[0] + "'");
            }
            if ("firstCrossing".equals(of) && Double.isNaN(crossing)) {
                problem(p, "of: firstCrossing needs `crossing`: the value whose first crossing is timed");
            }
            if (inOrder && (!"firstCrossing".equals(of) || bc == null || !Channels.isGroup(bc[0]))) {
                problem(p.key("inOrder"), "inOrder belongs to a group's firstCrossing (metric: body.NAME*.Q, of: firstCrossing)");
            }
            bounded = bounded || inOrder;
            if (e.has("between")) {
                channel = between(e.get("between"), p.key("between"), channel, kind, names);
            }
            if (e.has("minus") && e.get("minus").isObject()) {
                minusTrace = reference(e.get("minus"), p.key("minus"), channel, bc);
            } else if (e.has("minus")) {
                minus = e.get("minus").asText();
                String[] mc = Channels.bodyChannel(minus);
                if (mc == null && Channels.metricOf(minus) == null) {
                    problem(p.key("minus"), "unknown channel '" + minus + "' (see scenarios/README.md, Metrics)");
                } else if (mc != null && !names.contains(mc[0])) {
                    problem(p.key("minus"), "no body named '" + mc[0] + "' (minus takes one channel, not a group)");
                }
            }
            if (e.has("relativeTo")) {
                relativeTo = expectation(e.get("relativeTo"), p.key("relativeTo"), names, hasClosedForm, true);
                if (relativeTo != null && (relativeTo.kind() != ExpectationSpec.Kind.METRIC || relativeTo.group() != null)) {
                    problem(p.key("relativeTo"), "relativeTo is a figure of one channel: {metric: CHANNEL, of: R} or {metric: CHANNEL, at: T}");
                }
            }
            if ((of == null) == Double.isNaN(at)) {
                problem(p, "give `of` or `at`, one of them");
            }
            boolean errorOf = of != null && of.endsWith("Error");
            if (kind == ExpectationSpec.Kind.CLOSED_FORM) {
                if (!hasClosedForm) {
                    problem(cp, "a closedForm expectation needs reference.closedForm");
                }
                if (of != null && !errorOf) {
                    problem(p.key("of"), "a closedForm expectation reduces with maxError, finalError or rmsError");
                }
            } else if (errorOf) {
                problem(p.key("of"), of + " compares with the closed form: use `closedForm:` instead of `metric:`");
            }
            if (!bounded && !figure) {
                problem(p, "give atMost, atLeast or near with tolerance");
            }
            if (bounded && figure) {
                problem(p, "relativeTo is a figure: its bounds belong to the expectation");
            }
        } else {
            if (e.has("of") || e.has("at") || e.has("relative") || e.has("crossing") || e.has("inOrder")
                    || e.has("minus") || e.has("relativeTo") || e.has("between")) {
                problem(p, "of, at, relative, crossing, inOrder, minus, relativeTo and between belong to metric and "
                        + "closedForm expectations");
            }
        }
        double[] point = null;
        double[] max = null;
        if (kind == ExpectationSpec.Kind.ENDS_NEAR || kind == ExpectationSpec.Kind.STAYS_INSIDE) {
            if (body == null) {
                problem(p, k + " needs a body");
            }
            if (kind == ExpectationSpec.Kind.ENDS_NEAR) {
                point = vec(e.get("endsNear"), 0, 0);
                if (Double.isNaN(tolerance)) {
                    problem(p, "endsNear needs a tolerance (px)");
                }
            } else {
                point = vec(e.get("staysInside").get("min"), 0, 0);
                max = vec(e.get("staysInside").get("max"), 0, 0);
            }
        } else if (body != null) {
            problem(p.key("body"), "body belongs to endsNear and staysInside expectations");
        }
        double[] window = e.has("window") ? vec(e.get("window"), 0, 0) : new double[] {0, Double.POSITIVE_INFINITY};
        JsonNode stable = e.get("stable");
        return new ExpectationSpec(kind, channel, of, at, bool(e, "relative", false), body, point, max, atMost,
                atLeast, near, tolerance, window[0], window[1],
                stable != null ? num(stable, "maxSpeed", Double.NaN) : Double.NaN,
                stable != null ? num(stable, "maxAngularSpeed", Double.NaN) : Double.NaN,
                stable != null ? num(stable, "maxEnergyRise", Double.NaN) : Double.NaN,
                e.has("name") ? e.get("name").asText() : null, e.has("why") ? e.get("why").asText() : null,
                knownFailure(e.get("knownFailure")), p, crossing, inOrder, minus, relativeTo, minusTrace);
    }

    /**
     * A body name as an expectation writes it: a bare generator name stands for the generator's bodies
     * ({@code box} for {@code box[*]}), unless a body has that name too, which is refused as ambiguous.
     */
    private String group(String name, Set<String> names, JsonPath p) {
        if (!generators.contains(name)) {
            return name;
        }
        if (names.contains(name)) {
            problem(p, "'" + name + "' names both a body and the generator " + name + ": write " + name
                    + "[*] for the generator's bodies, or rename the body");
            return name;
        }
        return name + "[*]";
    }

    /**
     * {@code between: [A, B]}: a penetration channel narrowed to the pairs of which one body is A and the
     * other B (names, groups, bare generator names or {@code landscape}); registers the pair filter.
     */
    private String between(JsonNode list, JsonPath p, String channel, ExpectationSpec.Kind kind, Set<String> names) {
        String q = channel.startsWith("penetration.") ? channel.substring("penetration.".length()) : null;
        if (kind != ExpectationSpec.Kind.METRIC || q == null || !Channels.PAIR_QUANTITIES.contains(q)) {
            problem(p, "between narrows penetration.max, penetration.mean or penetration.points to pairs of bodies");
            return channel;
        }
        String[] party = new String[2];
        for (int i = 0; i < 2; i++) {
            String n = list.get(i).asText();
            JsonPath ip = p.index(i);
            if (n.equals(Channels.LANDSCAPE)) {
                if (names.contains(n) && hasLandscape) {
                    problem(ip, "'landscape' names both a body and the scene's landscape: rename the body");
                } else if (!names.contains(n) && !hasLandscape) {
                    problem(ip, "the scene has no landscape");
                }
                party[i] = n;
                continue;
            }
            party[i] = group(n, names, ip);
            if (!known(party[i], names)) {
                problem(ip, Channels.isGroup(party[i]) ? "'" + party[i] + "' matches no body"
                        : "no body named '" + n + "'" + (hasLandscape ? "" : " (and the scene has no landscape)"));
            }
        }
        pairFilters.add(new MetricSpec.PairSpec(party[0], party[1]));
        return Channels.pair(q, party[0], party[1]);
    }

    /**
     * {@code minus: {trace: FILE, channel: C}}: channel C (default the expectation's) of a stored trace,
     * the file relative to the scene's folder. Its sampling is checked against the scene's once it is read.
     */
    private ReferenceTrace reference(JsonNode m, JsonPath p, String channel, String[] bc) {
        if (bc != null && Channels.isGroup(bc[0])) {
            problem(p, "minus: {trace} takes one body's channel, not a group");
            return null;
        }
        String wanted = m.has("channel") ? m.get("channel").asText() : channel;
        ReferenceTraces.Found found = ReferenceTraces.read(Path.of(file), m.get("trace").asText(), wanted);
        if (found.problem() != null) {
            problem(p.key(found.problemAtChannel() ? "channel" : "trace"), found.problem());
        }
        return found.trace();
    }

    /** The channels an expectation reads besides its own: {@code minus} and {@code relativeTo}'s. */
    static List<String> extraChannels(ExpectationSpec e) {
        List<String> out = new ArrayList<>();
        if (e.minus() != null) {
            out.add(e.minus());
        }
        if (e.relativeTo() != null && e.relativeTo().channel() != null) {
            out.add(e.relativeTo().channel());
        }
        return out;
    }

    /** Whether a body name in an expectation names a body, or as a group ({@code *}) matches at least one. */
    private static boolean known(String name, Set<String> names) {
        if (names.contains(name)) {
            return true;
        }
        return Channels.isGroup(name) && names.stream().anyMatch(n -> Channels.matches(name, n));
    }

    private static MetricSpec.Kind neededMetric(ExpectationSpec e) {
        switch (e.kind()) {
            case METRIC:
            case CLOSED_FORM:
                return Channels.metricOf(Channels.base(e.channel()));
            case NO_TUNNELLING:
                return MetricSpec.Kind.tunnelling;
            case STABLE:
                return MetricSpec.Kind.stability;
            default:
                return null;
        }
    }

    private void checkBodyRefs(JsonNode node, JsonPath p, Set<String> names) {
        // Elements refer to bodies through these keys; a wrong name is caught before any builder runs.
        if (node.isArray()) {
            for (int i = 0; i < node.size(); i++) {
                checkBodyRefs(node.get(i), p.index(i), names);
            }
        } else if (node.isObject()) {
            for (String key : List.of("body", "bodyA", "bodyB")) {
                JsonNode v = node.get(key);
                if (v != null && v.isTextual() && !names.contains(v.asText())) {
                    problem(p.key(key), "no body named '" + v.asText() + "'");
                }
            }
        }
    }

    private static KnownFailure knownFailure(JsonNode k) {
        if (k == null) {
            return null;
        }
        return new KnownFailure(k.get("reason").asText(), k.get("measured").asText(),
                k.has("issue") ? k.get("issue").asText() : null);
    }

    private static double[] vec(JsonNode v, double dx, double dy) {
        return v == null ? new double[] {dx, dy} : new double[] {v.get(0).asDouble(), v.get(1).asDouble()};
    }

    private static double num(JsonNode o, String key, double dflt) {
        return o.has(key) ? o.get(key).asDouble() : dflt;
    }

    private static boolean bool(JsonNode o, String key, boolean dflt) {
        return o.has(key) ? o.get(key).asBoolean() : dflt;
    }

    private static String known(Set<String> names) {
        return names.isEmpty() ? "" : " (known: " + String.join(", ", names) + ")";
    }

    private void problem(JsonPath path, String message) {
        int[] at = sourceMap.locate(path);
        problems.add(new Problem(file, at[0], at[1], path.toString(), message));
    }
}
