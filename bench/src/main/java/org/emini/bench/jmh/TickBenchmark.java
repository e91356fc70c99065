package org.emini.bench.jmh;

import com.google.gson.GsonBuilder;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.emini.bench.check.Stability;
import org.emini.bench.engine.BenchEngine;
import org.emini.bench.engine.Engines;
import org.emini.bench.engine.UnsupportedSceneException;
import org.emini.bench.scene.BenchScenes;
import org.emini.harness.scenario.Scenario;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.infra.IterationParams;
import org.openjdk.jmh.runner.IterationType;

/**
 * One operation is one tick of a scene in one engine. The trial starts from the scene as its file
 * builds it and first runs {@code preroll} ticks (by default the scene's whole run duration, so a
 * pyramid has settled and rain has landed): that untimed run is also the stability check, the same
 * number of ticks in every engine. JMH then times ticks of the settled scene (steady state); the
 * scene is checked again at the end of the trial.
 *
 * <p>Checks go to {@code <emini.bench.out>/<scene>__<engine>.json} when that system property is set.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class TickBenchmark {
    /** Scene id under scenarios/. */
    @Param({"bench/pyramid-20"})
    public String scene;

    /** Engine id (see {@link Engines}). */
    @Param({"emini"})
    public String engine;

    /** Untimed ticks before timing; -1 for the scene's run duration. */
    @Param({"-1"})
    public int preroll;

    private BenchEngine e;
    private Scenario scenario;
    private double[] initial;
    private long ticks;
    private final Map<String, Object> record = new LinkedHashMap<>();
    private final com.sun.management.ThreadMXBean threads =
        (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
    private boolean measuring;
    private long iterationTicks;
    private long iterationCpu;
    private long measuredTicks;
    private long measuredCpu;
    private long iterationBytes;
    private long measuredBytes;

    /** Builds the world, runs the preroll and checks it. */
    @Setup(Level.Trial)
    public void setUp() throws UnsupportedSceneException {
        scenario = BenchScenes.open().load(scene);
        e = Engines.create(engine);
        long t0 = System.nanoTime();
        e.build(scenario);
        long t1 = System.nanoTime();
        int n = e.bodyCount();
        initial = new double[3 * n];
        e.poses(initial);
        long p = preroll < 0 ? scenario.ticks() : preroll;
        for (long i = 0; i < p; i++) {
            e.tick();
        }
        long t2 = System.nanoTime();
        ticks = p;
        record.put("scene", scene);
        record.put("engine", engine);
        record.put("bodies", n);
        record.put("dynamicBodies", Stability.moving(scenario));
        record.put("settings", e.settings());
        record.put("buildMillis", (t1 - t0) / 1e6);
        record.put("prerollTicks", p);
        record.put("prerollMillisPerTick", p > 0 ? (t2 - t1) / 1e6 / p : null);
        record.put("check", check());
        write();
    }

    /**
     * Starts counting the thread's CPU time and allocated bytes over a measurement iteration: on a
     * shared, loaded machine the CPU time a tick takes is steadier than its wall time, and the
     * thread's own allocation counter is exact where JMH's GC profiler includes its own threads.
     */
    @Setup(Level.Iteration)
    public void startIteration(IterationParams params) {
        measuring = params.getType() == IterationType.MEASUREMENT;
        iterationTicks = ticks;
        iterationCpu = threads.getCurrentThreadCpuTime();
        iterationBytes = threads.getCurrentThreadAllocatedBytes();
    }

    /** Adds the iteration's CPU time and ticks. */
    @TearDown(Level.Iteration)
    public void endIteration() {
        if (measuring) {
            measuredBytes += threads.getCurrentThreadAllocatedBytes() - iterationBytes;
            measuredCpu += threads.getCurrentThreadCpuTime() - iterationCpu;
            measuredTicks += ticks - iterationTicks;
        }
    }

    /** One tick. */
    @Benchmark
    public void tick() {
        e.tick();
        ticks++;
    }

    /** Checks the scene again after the timed ticks. */
    @TearDown(Level.Trial)
    public void tearDown() {
        record.put("measuredTicks", measuredTicks);
        record.put("cpuMicrosPerTick", measuredTicks > 0 ? measuredCpu / 1e3 / measuredTicks : null);
        record.put("threadBytesPerTick", measuredTicks > 0 ? (double) measuredBytes / measuredTicks : null);
        record.put("afterRun", check());
        write();
        e.close();
    }

    private Stability check() {
        int n = e.bodyCount();
        double[] now = new double[3 * n];
        double[] speeds = new double[n];
        double[] omegas = new double[n];
        e.poses(now);
        e.speeds(speeds);
        e.angularVelocities(omegas);
        int np = e.particleCount();
        double[] particles = new double[2 * np];
        e.particlePositions(particles);
        return Stability.judge(scenario, ticks, initial, now, speeds, omegas, particles, np).withAsleep(e.sleepingCount());
    }

    private void write() {
        String dir = System.getProperty("emini.bench.out");
        if (dir == null) {
            return;
        }
        try {
            Path d = Path.of(dir);
            Files.createDirectories(d);
            String json = new GsonBuilder().serializeSpecialFloatingPointValues().setPrettyPrinting().create().toJson(record);
            Files.writeString(d.resolve(fileName(scene, engine)), json, StandardCharsets.UTF_8);
        } catch (IOException x) {
            throw new UncheckedIOException(x);
        }
    }

    /** The check file's name for a scene and engine. */
    public static String fileName(String scene, String engine) {
        return scene.replace('/', '_') + "__" + engine + ".json";
    }
}
