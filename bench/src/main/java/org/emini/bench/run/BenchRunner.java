package org.emini.bench.run;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.reflect.TypeToken;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.emini.bench.engine.BenchEngine;
import org.emini.bench.engine.Engines;
import org.emini.bench.engine.UnsupportedSceneException;
import org.emini.bench.jmh.TickBenchmark;
import org.emini.bench.scene.BenchScenes;
import org.emini.harness.scenario.Scenario;
import org.openjdk.jmh.profile.GCProfiler;
import org.openjdk.jmh.results.Result;
import org.openjdk.jmh.results.RunResult;
import org.openjdk.jmh.runner.Runner;
import org.openjdk.jmh.runner.RunnerException;
import org.openjdk.jmh.runner.options.ChainedOptionsBuilder;
import org.openjdk.jmh.runner.options.OptionsBuilder;
import org.openjdk.jmh.runner.options.TimeValue;

/** Runs {@link TickBenchmark} for one scene and engine with JMH and collects a {@link Measurement}. */
public final class BenchRunner {
    private final BenchScenes scenes;
    private final BenchPlan.Mode mode;
    private final Path checks;
    private final Path log;
    // Results measure() took from an earlier run instead of measuring.
    private int reused;

    /**
     * @param scenes the library
     * @param mode JMH settings
     * @param checks folder for the benchmark's scene checks
     * @param log folder for JMH's own output, one file per scene and engine
     */
    public BenchRunner(BenchScenes scenes, BenchPlan.Mode mode, Path checks, Path log) {
        this.scenes = scenes;
        this.mode = mode;
        this.checks = checks;
        this.log = log;
    }

    /**
     * Measures a scene in an engine and keeps the result in {@code measurements/}. With {@code resume},
     * a result already kept (or one a finished JMH run left in its log and check files) is reused.
     */
    public Measurement measure(String sceneId, String engineId, boolean resume) {
        Path kept = checks.getParent().resolve("measurements").resolve(TickBenchmark.fileName(sceneId, engineId));
        Gson gson = new GsonBuilder().setPrettyPrinting().serializeNulls().serializeSpecialFloatingPointValues().create();
        try {
            if (resume) {
                Measurement m = Files.isRegularFile(kept)
                    ? gson.fromJson(Files.readString(kept, StandardCharsets.UTF_8), Measurement.class)
                    : fromLogs(sceneId, engineId);
                if (m != null) {
                    reused++;
                    return m;
                }
            }
            Measurement m = measure(sceneId, engineId);
            Files.createDirectories(kept.getParent());
            Files.writeString(kept, gson.toJson(m), StandardCharsets.UTF_8);
            return m;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** How many results {@link #measure} reused from an earlier run instead of measuring. */
    public int reused() {
        return reused;
    }

    /** A finished run's result read back from JMH's log and the check file, or null. */
    private Measurement fromLogs(String sceneId, String engineId) throws IOException {
        Path checkFile = checks.resolve(TickBenchmark.fileName(sceneId, engineId));
        Path logFile = log.resolve(TickBenchmark.fileName(sceneId, engineId).replace(".json", ".log"));
        Map<String, Object> rec = readCheck(checkFile);
        if (rec == null || !rec.containsKey("afterRun") || !Files.isRegularFile(logFile)) {
            return null;
        }
        Double score = null, error = null, alloc = null;
        List<Double> iterations = new ArrayList<>();
        for (String line : Files.readAllLines(logFile, StandardCharsets.UTF_8)) {
            String[] w = line.trim().split("\\s+");
            if (line.startsWith("Iteration ") && w.length >= 3) {
                iterations.add(parse(w[2]));
            } else if (line.startsWith("TickBenchmark.tick ") && w.length >= 9 && "±".equals(w[w.length - 3])) {
                score = parse(w[w.length - 4]);
                error = parse(w[w.length - 2]);
            } else if (line.startsWith("TickBenchmark.tick:gc.alloc.rate.norm") && w.length >= 9) {
                alloc = parse("±".equals(w[w.length - 3]) ? w[w.length - 4] : w[w.length - 2]);
            }
        }
        if (score == null || iterations.isEmpty()) {
            return null;
        }
        iterations.sort(null);
        Scenario scenario = scenes.load(sceneId);
        long dynamic = org.emini.bench.check.Stability.moving(scenario);
        return result(sceneId, engineId, scenario, dynamic, score / 1000.0, error == null ? null : error / 1000.0,
            iterations.get(iterations.size() / 2) / 1000.0, alloc, rec);
    }

    private static Double parse(String s) {
        try {
            return Double.valueOf(s);
        } catch (NumberFormatException e) {
            return null;
        }
    }

    private Measurement measure(String sceneId, String engineId) {
        Scenario scenario;
        try {
            scenario = scenes.load(sceneId);
        } catch (IllegalArgumentException e) {
            return Measurement.notRun(sceneId, engineId, "error", e.getMessage());
        }
        // Unsupported elements are found here, before JMH forks a JVM for nothing.
        try (BenchEngine e = Engines.create(engineId)) {
            e.build(scenario);
        } catch (UnsupportedSceneException e) {
            return Measurement.notRun(sceneId, engineId, "unsupported", e.getMessage());
        } catch (RuntimeException e) {
            return Measurement.notRun(sceneId, engineId, "error", e.toString());
        }
        Path checkFile = checks.resolve(TickBenchmark.fileName(sceneId, engineId));
        Path logFile = log.resolve(TickBenchmark.fileName(sceneId, engineId).replace(".json", ".log"));
        try {
            Files.deleteIfExists(checkFile);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        String root = scenes.root().toString();
        System.setProperty("emini.bench.out", checks.toString());
        System.setProperty("emini.root", root);
        ChainedOptionsBuilder o = new OptionsBuilder()
            .include(TickBenchmark.class.getName() + ".tick$")
            .param("scene", sceneId)
            .param("engine", engineId)
            .param("preroll", Integer.toString(mode.preroll()))
            .forks(mode.forks())
            .warmupIterations(mode.warmups())
            .warmupTime(TimeValue.milliseconds(mode.warmupMillis()))
            .measurementIterations(mode.iterations())
            .measurementTime(TimeValue.milliseconds(mode.iterationMillis()))
            .timeUnit(TimeUnit.MICROSECONDS)
            .addProfiler(GCProfiler.class)
            .shouldFailOnError(true)
            .output(logFile.toString())
            .jvmArgsAppend("-Demini.bench.out=" + checks, "-Demini.root=" + root, "-Xms1g", "-Xmx4g", "-Djava.awt.headless=true");
        Collection<RunResult> results;
        try {
            results = new Runner(o.build()).run();
        } catch (RunnerException e) {
            return Measurement.notRun(sceneId, engineId, "error", "JMH: " + e.getMessage() + " (see " + logFile + ")");
        }
        if (results.isEmpty()) {
            return Measurement.notRun(sceneId, engineId, "error", "JMH returned no result (see " + logFile + ")");
        }
        RunResult r = results.iterator().next();
        Result<?> primary = r.getPrimaryResult();
        double ms = primary.getScore() / 1000.0;
        double err = primary.getScoreError() / 1000.0;
        double median = primary.getStatistics().getPercentile(50) / 1000.0;
        Result<?> alloc = r.getSecondaryResults().get("gc.alloc.rate.norm");
        Map<String, Object> rec = readCheck(checkFile);
        long dynamic = org.emini.bench.check.Stability.moving(scenario);
        return result(sceneId, engineId, scenario, dynamic, ms, Double.isNaN(err) ? null : err, median,
            alloc == null ? null : alloc.getScore(), rec);
    }

    private static Measurement result(String sceneId, String engineId, Scenario scenario, long dynamic, double ms, Double err,
                                      double median, Double alloc, Map<String, Object> rec) {
        Double cpuUs = rec == null ? null : (Double) rec.get("cpuMicrosPerTick");
        Double cpuMs = cpuUs == null ? null : cpuUs / 1000.0;
        Double cost = cpuMs != null ? cpuMs : ms;
        @SuppressWarnings("unchecked")
        Map<String, Object> check = rec == null ? null : (Map<String, Object>) rec.get("check");
        @SuppressWarnings("unchecked")
        Map<String, Object> after = rec == null ? null : (Map<String, Object>) rec.get("afterRun");
        return new Measurement(sceneId, engineId, "ok", "", scenario.bodies().size(), dynamic, ms, err, median, cpuMs,
            cost * 1000.0 / Math.max(1, dynamic), alloc, rec == null ? null : (Double) rec.get("threadBytesPerTick"),
            rec == null ? null : (Double) rec.get("prerollMillisPerTick"),
            rec == null ? null : (String) rec.get("settings"), check, after);
    }

    private static Map<String, Object> readCheck(Path f) {
        if (!Files.isRegularFile(f)) {
            return null;
        }
        try {
            return new Gson().fromJson(Files.readString(f, StandardCharsets.UTF_8),
                new TypeToken<Map<String, Object>>() { }.getType());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
