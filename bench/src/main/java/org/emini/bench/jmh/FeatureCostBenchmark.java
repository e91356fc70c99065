package org.emini.bench.jmh;

import com.google.gson.Gson;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.emini.bench.scene.BenchScenes;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.event.Event;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.build.UnsupportedElementException;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import org.emini.harness.metrics.Metric;
import org.emini.harness.metrics.Metrics;
import org.emini.harness.scenario.MetricSpec;
import org.emini.harness.scenario.Scenario;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import org.openjdk.jmh.infra.IterationParams;
import org.openjdk.jmh.runner.IterationType;
import org.yaml.snakeyaml.Yaml;

/**
 * "A scene pays only for what it uses" (issue 5), measured on the plain 20-row pyramid
 * ({@code scenarios/bench/pyramid-20.yaml}, 210 boxes, built by the harness's {@link WorldBuilder}).
 * Worlds:
 *
 * <ul>
 *   <li>{@code plain}: the scene as it is.
 *   <li>{@code idle}: the same scene with every other feature present but idle: a landscape segment
 *       5000 px away, a particle emitter with rate 0 (it never has a particle), two weightless bodies
 *       at rest 5000 px away joined by a pin joint and a Hooke spring at its rest length, three events
 *       (position, velocity, collision) with no listener, and no harness metric requested.
 *   <li>{@code metrics}: the plain scene with every harness metric that applies (energy, both momenta,
 *       penetration, constraint error, stability) sampled after every tick, as {@code harness run} does
 *       with {@code record.every} at one tick: what metrics cost when a scene asks for them.
 * </ul>
 *
 * <p>The {@code variant} param picks one world per fork (one operation = one tick), or a pair:
 * {@code paired} (plain and idle), {@code pairedMetrics} (plain and metrics) or {@code pairedPlain} (plain
 * and a second plain world: the pairing's own bias, the resolution of the other two) side by side in one JVM,
 * one operation ticking each once (in turns: plain first on even operations, the other first on odd
 * ones), each tick timed by the thread's CPU clock. On a loaded machine the paired figures are the ones
 * to compare: both worlds meet the same load and the same JIT state. Every world first runs the scene's duration (10 s, 600 ticks) untimed, so the
 * pyramid has settled. At the end of each fork the thread's CPU time per tick is printed
 * ({@code cpu ms/tick}; for {@code paired}, per world and their ratio).
 *
 * <pre>
 * java -cp "bench/target/classes:harness/target/classes:engine/target/classes:bench/target/lib/*" \
 *   org.openjdk.jmh.Main FeatureCostBenchmark -p variant=paired -f 5
 * </pre>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Fork(3)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
public class FeatureCostBenchmark {
    /** Which world: {@code plain}, {@code idle}, {@code metrics}; or a pair in turns: {@code paired}
     * (plain and idle), {@code pairedMetrics} (plain and metrics), {@code pairedPlain} (plain twice). */
    @Param({"plain", "idle", "metrics", "paired", "pairedMetrics", "pairedPlain"})
    public String variant;

    private Ticked first;
    private Ticked second;
    private final com.sun.management.ThreadMXBean threads =
        (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
    private boolean measuring;
    private long ops;

    /** A world and the metrics ticked with it, with the CPU time its measured ticks took. */
    private static final class Ticked {
        final String name;
        final World world;
        final Metric[] metrics;
        final int[] widths;
        final double[] row;
        long cpu;
        long ticks;

        Ticked(String name, World world, List<Metric> metrics) {
            this.name = name;
            this.world = world;
            this.metrics = metrics.toArray(new Metric[0]);
            widths = metrics.stream().mapToInt(m -> m.channels().size()).toArray();
            row = new double[java.util.Arrays.stream(widths).sum()];
        }

        /** One tick and the metrics, as the harness runner does; returns something to consume. */
        double tick() {
            world.tick();
            int offset = 0;
            for (int i = 0; i < metrics.length; i++) {
                metrics[i].afterTick();
                metrics[i].sample(row, offset);
                offset += widths[i];
            }
            return metrics.length > 0 ? row[0] : world.getBody(world.getBodyCount() - 1).getY();
        }
    }

    /** Builds the variant's world(s) and lets each pyramid settle. */
    @Setup(Level.Trial)
    public void setUp() throws UnsupportedElementException, IOException {
        if (variant.startsWith("paired")) {
            first = build("plain");
            second = build(variant.equals("paired") ? "idle" : variant.equals("pairedMetrics") ? "metrics" : "plain");
        } else {
            first = build(variant);
        }
    }

    private static Ticked build(String kind) throws UnsupportedElementException, IOException {
        Path lib = BenchScenes.findRoot().resolve("scenarios");
        String text = Files.readString(lib.resolve("bench/pyramid-20.yaml"));
        if (kind.equals("idle")) {
            text = withIdleFeatures(text);
        }
        ScenarioLoader.Loaded loaded = new ScenarioLoader(SchemaCheck.fromFile(lib.resolve("scenario.schema.json")), lib)
            .load("bench/pyramid-20 (" + kind + ")", text, "bench/pyramid-20-" + kind);
        if (!loaded.ok()) {
            throw new IllegalStateException(loaded.problems().stream().map(Object::toString).collect(Collectors.joining("; ")));
        }
        Scenario scenario = loaded.scenario();
        BuiltWorld built = WorldBuilder.build(scenario);
        World world = built.world();
        List<Metric> metrics = new ArrayList<>();
        if (kind.equals("idle")) {
            Body apex = built.body("box[209]");
            world.addEvent(Event.createPositionEvent(apex, null, 4000f, 4000f, 5000f, 5000f));
            world.addEvent(Event.createVelocityEvent(apex, null, 1000f, 2000f));
            world.addEvent(Event.createCollisionEvent(apex, null, true, true, true, true));
        }
        if (kind.equals("metrics")) {
            for (MetricSpec.Kind k : List.of(MetricSpec.Kind.energy, MetricSpec.Kind.linearMomentum,
                    MetricSpec.Kind.angularMomentum, MetricSpec.Kind.penetration, MetricSpec.Kind.constraintError,
                    MetricSpec.Kind.stability)) {
                metrics.add(Metrics.create(MetricSpec.plain(k, null), built));
            }
        }
        Ticked t = new Ticked(kind, world, metrics);
        for (long i = 0; i < scenario.ticks(); i++) {
            t.tick();
        }
        return t;
    }

    /**
     * The pyramid scene with the idle features added (the scene file is YAML; the result is its JSON
     * form, which the loader reads the same way).
     */
    @SuppressWarnings("unchecked")
    static String withIdleFeatures(String yaml) {
        Map<String, Object> scene = new Yaml().load(yaml);
        // The two far bodies come after the pyramid (a generator after its generator), so the pyramid's
        // bodies keep their indices and the plain and idle pyramids are the same world.
        List<Object> generators = (List<Object>) scene.get("generators");
        Map<String, Object> far = new LinkedHashMap<>();
        far.put("type", "row");
        far.put("name", "far");
        far.put("shape", Map.of("type", "circle", "radius", 5));
        far.put("start", List.of(5000, -5000));
        far.put("count", 2);
        far.put("spacing", List.of(30, 0));
        far.put("body", Map.of("gravity", false));
        generators.add(far);
        scene.put("joints", List.of(Map.of("bodyA", "far[0]", "bodyB", "far[1]", "at", List.of(5015, -5000))));
        scene.put("springs", List.of(Map.of("bodyA", "far[0]", "bodyB", "far[1]", "stiffness", 10, "damping", 1)));
        scene.put("landscape", Map.of("segments", List.of(Map.of("from", List.of(-5000, 5000), "to", List.of(-4000, 5000)))));
        scene.put("particles", List.of(Map.of("name", "idle", "from", List.of(-5000, 4000), "rate", 0)));
        return new Gson().toJson(scene);
    }

    /** Counts CPU time only over measurement iterations. */
    @Setup(Level.Iteration)
    public void startIteration(IterationParams params) {
        measuring = params.getType() == IterationType.MEASUREMENT;
    }

    /** Prints the fork's CPU time per tick. */
    @TearDown(Level.Trial)
    public void tearDown() {
        StringBuilder line = new StringBuilder();
        for (Ticked t : second == null ? List.of(first) : List.of(first, second)) {
            World w = t.world;
            line.append(String.format(" %s %.4f [%d bodies, %d segments, %d emitters, %d particles, %d constraints,"
                + " %d events, %d metrics]", t.name, t.cpu / 1e6 / Math.max(1, t.ticks), w.getBodyCount(),
                w.getLandscape().getSegmentCount(), w.getParticleEmitterCount(),
                w.getParticleEmitterCount() > 0 ? w.getParticleEmitter(0).getParticleCount() : 0, w.getConstraintCount(),
                w.getEventCount(), t.metrics.length));
        }
        if (second != null) {
            double a = first.cpu / (double) Math.max(1, first.ticks);
            double b = second.cpu / (double) Math.max(1, second.ticks);
            line.append(String.format(" %s/plain %.4f", second.name, b / a));
        }
        System.out.printf("%ncpu ms/tick (%s):%s over %d ticks each%n", variant, line, first.ticks);
    }

    /** One tick of the variant's world; {@code paired}: one tick of each, in turns, each timed. */
    @Benchmark
    public double tick() {
        if (second == null) {
            long t0 = measuring ? threads.getCurrentThreadCpuTime() : 0;
            double v = first.tick();
            if (measuring) {
                first.cpu += threads.getCurrentThreadCpuTime() - t0;
                first.ticks++;
            }
            return v;
        }
        boolean plainFirst = (ops++ & 1) == 0;
        return timed(plainFirst ? first : second) + timed(plainFirst ? second : first);
    }

    private double timed(Ticked t) {
        long t0 = threads.getCurrentThreadCpuTime();
        double v = t.tick();
        if (measuring) {
            t.cpu += threads.getCurrentThreadCpuTime() - t0;
            t.ticks++;
        }
        return v;
    }
}
