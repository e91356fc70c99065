package org.emini.bench.jmh;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.emini.bench.scene.BenchScenes;
import org.emini.harness.build.UnsupportedElementException;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.scenario.Scenario;
import org.emini.world.World;
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

/**
 * What sleeping saves (issue 17: "ten 20-row pyramids once settled and asleep cost under 5% of their
 * awake tick"): a tick of {@code scenarios/bench/pyramids-10x20.yaml} (2,100 boxes, built by the
 * harness's {@link WorldBuilder}) with sleeping off ({@code awake}: every box simulated every tick,
 * as the other benchmark scenes run) and with sleeping on ({@code asleep}: the scene with
 * {@code world.sleeping} forced on). Both worlds first run the scene's duration (10 s, 600 ticks)
 * untimed, so both pyramids have settled and the second has fallen asleep; the setup refuses to time
 * it unless every box sleeps and none does in the awake world. Param {@code scene} runs another scene
 * the same way ({@code bench/game-level}: the 840 crates must sleep; its swinging balls, held by
 * joints, and its players, which may not sleep, stay awake).
 *
 * <p>The {@code variant} param picks one world per fork (one operation = one tick), or
 * {@code paired}: both worlds in one JVM, one operation ticking each once (in turns: the awake one
 * first on even operations, the asleep one first on odd ones), each tick timed by the thread's CPU
 * clock, so both meet the same load and the same JIT state; on a loaded machine that is the figure to
 * quote. At the end of each fork the thread's CPU time per tick is printed ({@code cpu ms/tick}; for
 * {@code paired}, per world and their ratio, {@code asleep/awake}).
 *
 * <pre>
 * java -cp "bench/target/classes:harness/target/classes:engine/target/classes:bench/target/lib/*" \
 *   org.openjdk.jmh.Main SleepCostBenchmark -p variant=paired -f 1 -wi 2 -i 3
 * </pre>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Fork(1)
@Warmup(iterations = 2, time = 1)
@Measurement(iterations = 3, time = 1)
public class SleepCostBenchmark {
    /** The scene (its id under scenarios/): ten 20-row pyramids. */
    @Param({"bench/pyramids-10x20"})
    public String scene;

    /** Which world: {@code awake}, {@code asleep}, or both in turns: {@code paired}. */
    @Param({"paired", "awake", "asleep"})
    public String variant;

    private Ticked first;
    private Ticked second;
    private final com.sun.management.ThreadMXBean threads =
        (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
    private boolean measuring;
    private long ops;

    /** A settled world and the CPU time its measured ticks took. */
    static final class Ticked {
        final String name;
        final World world;
        long cpu;
        long ticks;

        Ticked(String name, World world) {
            this.name = name;
            this.world = world;
        }

        /** Bodies asleep now. */
        int asleep() {
            int n = 0;
            for (int i = 0; i < world.getBodyCount(); i++) {
                n += world.getBody(i).isSleeping() ? 1 : 0;
            }
            return n;
        }

        /** Dynamic bodies. */
        int dynamic() {
            int n = 0;
            for (int i = 0; i < world.getBodyCount(); i++) {
                n += world.getBody(i).isDynamic() ? 1 : 0;
            }
            return n;
        }
    }

    /** Builds the variant's world(s) and lets each settle (and the asleep one fall asleep). */
    @Setup(Level.Trial)
    public void setUp() throws UnsupportedElementException {
        if (variant.equals("paired")) {
            first = settled(scene, false);
            second = settled(scene, true);
        } else {
            first = settled(scene, variant.equals("asleep"));
        }
    }

    /**
     * The scene's world after its run duration, sleeping on or off; refuses a world whose bodies did
     * not all fall asleep (or, awake, any that did), since it would not measure what it says.
     */
    static Ticked settled(String id, boolean sleeping) throws UnsupportedElementException {
        Scenario scene = BenchScenes.open().load(id).withSleeping(sleeping);
        Ticked t = new Ticked(sleeping ? "asleep" : "awake", WorldBuilder.build(scene).world());
        for (long i = 0; i < scene.ticks(); i++) {
            t.world.tick();
        }
        int asleep = t.asleep();
        int resting = resting(scene);
        if (sleeping ? asleep != resting : asleep != 0) {
            throw new IllegalStateException(t.name + " world: " + asleep + " bodies asleep after " + scene.ticks()
                + " ticks, expected " + (sleeping ? resting : 0));
        }
        return t;
    }

    /** The dynamic bodies that should sleep once settled: all but those that may not or that a joint holds. */
    static int resting(Scenario scene) {
        java.util.Set<String> held = new java.util.HashSet<>();
        if (scene.elements().containsKey("joints")) {
            for (com.fasterxml.jackson.databind.JsonNode j : scene.elements().get("joints").node()) {
                held.add(j.get("bodyA").asText());
                held.add(j.get("bodyB").asText());
            }
        }
        return (int) scene.bodies().stream().filter(b -> !b.state().isStatic() && b.state().sleepingAllowed()
            && !held.contains(b.name())).count();
    }

    /** Counts CPU time only over measurement iterations. */
    @Setup(Level.Iteration)
    public void startIteration(IterationParams params) {
        measuring = params.getType() == IterationType.MEASUREMENT;
    }

    /** Prints the fork's CPU time per tick, and the ratio when paired. */
    @TearDown(Level.Trial)
    public void tearDown() {
        StringBuilder line = new StringBuilder();
        for (Ticked t : second == null ? List.of(first) : List.of(first, second)) {
            line.append(String.format(java.util.Locale.ROOT, " %s %.4f [%d of %d bodies asleep]", t.name,
                t.cpu / 1e6 / Math.max(1, t.ticks), t.asleep(), t.world.getBodyCount()));
        }
        if (second != null) {
            double a = first.cpu / (double) Math.max(1, first.ticks);
            double b = second.cpu / (double) Math.max(1, second.ticks);
            line.append(String.format(java.util.Locale.ROOT, " asleep/awake %.4f", b / a));
        }
        System.out.printf("%ncpu ms/tick (%s):%s over %d ticks each%n", variant, line, first.ticks);
    }

    /** One tick of the variant's world; {@code paired}: one tick of each, in turns, each timed. */
    @Benchmark
    public double tick() {
        if (second == null) {
            return timed(first);
        }
        boolean awakeFirst = (ops++ & 1) == 0;
        return timed(awakeFirst ? first : second) + timed(awakeFirst ? second : first);
    }

    private double timed(Ticked t) {
        long t0 = measuring ? threads.getCurrentThreadCpuTime() : 0;
        t.world.tick();
        if (measuring) {
            t.cpu += threads.getCurrentThreadCpuTime() - t0;
            t.ticks++;
        }
        return t.world.getBody(t.world.getBodyCount() - 1).getY();
    }
}
