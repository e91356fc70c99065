package org.emini.harness.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.LongConsumer;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.load.Problem;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.report.TraceWriter;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.Status;
import org.emini.harness.scenario.SceneScaling;

/**
 * The engine's side of {@code run} and {@code compare}: every valid scene run on a pool of threads
 * ({@link ScenarioRunner}: build, tick, measure, judge), its trace written as its run ends. Results
 * are read back in the order the caller asks, so the commands print in file order whatever finishes
 * first.
 */
final class SceneBatch implements AutoCloseable {
    /**
     * What the batch does with each run.
     *
     * @param traces the folder traces are written to, or null for none
     * @param everyTrace write every run's trace ({@code compare} pairs each with the oracle's), not only
     *     those whose scene records one ({@code run})
     * @param keepTraces keep traces in the results ({@code compare} reads them); {@code run} drops them
     *     once written, so a library of long scenes fits in memory
     * @param timeoutSeconds wall-clock time a scene may tick before it stops as ERROR
     * @param ticks told how many ticks were just done (a progress bar)
     * @param workers the threads each scene's world shares its ticks among ({@code run --workers}; 1 for none)
     */
    record Settings(Path traces, boolean everyTrace, boolean keepTraces, double timeoutSeconds, LongConsumer ticks,
                    int workers) {
    }

    private final ExecutorService pool;
    private final Map<ScenarioLoader.Loaded, Future<SceneResult>> runs = new IdentityHashMap<>();

    /** Starts every valid scene on {@code threads} threads. */
    SceneBatch(List<ScenarioLoader.Loaded> scenes, int threads, Settings settings) {
        pool = Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "scene");
            t.setDaemon(true);
            return t;
        });
        for (ScenarioLoader.Loaded l : scenes) {
            if (l.ok()) {
                runs.put(l, pool.submit(() -> run(l, settings)));
            }
        }
    }

    /** Loads every file; an invalid one stays in the list, with its problems. */
    static List<ScenarioLoader.Loaded> load(ScenarioLoader loader, List<Path> files) {
        List<ScenarioLoader.Loaded> loaded = new ArrayList<>();
        for (Path f : files) {
            loaded.add(loader.load(f));
        }
        return loaded;
    }

    /**
     * The scenes with sleeping forced on or off ({@code run --sleeping}), each keeping the tolerances
     * it gives; invalid scenes stay as they are.
     */
    static List<ScenarioLoader.Loaded> withSleeping(List<ScenarioLoader.Loaded> scenes, boolean on) {
        List<ScenarioLoader.Loaded> out = new ArrayList<>();
        for (ScenarioLoader.Loaded l : scenes) {
            out.add(l.ok() ? new ScenarioLoader.Loaded(l.file(), l.scenario().withSleeping(on), l.problems()) : l);
        }
        return out;
    }

    /**
     * The scenes with the engine's speculative distance times {@code factor} ({@code run --nudge},
     * {@link Scenario#withNudge}); invalid scenes stay as they are.
     */
    static List<ScenarioLoader.Loaded> nudged(List<ScenarioLoader.Loaded> scenes, double factor) {
        double defaultDistance = WorldBuilder.defaultSpeculativeDistance();
        List<ScenarioLoader.Loaded> out = new ArrayList<>();
        for (ScenarioLoader.Loaded l : scenes) {
            out.add(l.ok() ? new ScenarioLoader.Loaded(l.file(), l.scenario().withNudge(factor, defaultDistance),
                    l.problems()) : l);
        }
        return out;
    }

    /**
     * The scenes at k times their size ({@code run --scale}, {@link SceneScaling}); a scene the scaling
     * does not cover becomes invalid, with the reason.
     */
    static List<ScenarioLoader.Loaded> scaled(List<ScenarioLoader.Loaded> scenes, double k) {
        List<ScenarioLoader.Loaded> out = new ArrayList<>();
        for (ScenarioLoader.Loaded l : scenes) {
            if (!l.ok()) {
                out.add(l);
                continue;
            }
            try {
                out.add(new ScenarioLoader.Loaded(l.file(), SceneScaling.scale(l.scenario(), k), l.problems()));
            } catch (IllegalArgumentException e) {
                out.add(new ScenarioLoader.Loaded(l.file(), null, List.of(new Problem(l.scenario().file(), 0, 0, "$",
                        "--scale " + k + ": " + e.getMessage()))));
            }
        }
        return out;
    }

    /** A scene's result, once its run has ended; an invalid scene's is an ERROR naming its problems. */
    SceneResult result(ScenarioLoader.Loaded l) throws IOException, InterruptedException {
        if (!l.ok()) {
            return invalid(l);
        }
        try {
            return runs.get(l).get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof UncheckedIOException io) {
                throw io.getCause();
            }
            throw new IllegalStateException(e.getCause());
        }
    }

    @Override
    public void close() {
        pool.shutdownNow();
    }

    private static SceneResult run(ScenarioLoader.Loaded l, Settings settings) {
        SceneResult r = ScenarioRunner.run(l.scenario(), settings.ticks(), settings.timeoutSeconds(),
                settings.workers());
        if (settings.traces() != null && r.trace() != null && (settings.everyTrace() || l.scenario().run().record().trace())) {
            try {
                TraceWriter.write(TraceWriter.fileFor(settings.traces(), r.scene()), r.scene(), "emini", r.trace());
                if (r.replay() != null) {
                    TraceWriter.writeReplay(TraceWriter.replayFor(settings.traces(), r.scene()), r.replay().json());
                }
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return settings.keepTraces() ? r : r.withoutTrace();
    }

    private static SceneResult invalid(ScenarioLoader.Loaded l) {
        StringBuilder msg = new StringBuilder("invalid scene:");
        for (Problem p : l.problems()) {
            msg.append("\n    ").append(p);
        }
        return new SceneResult(l.file().toString(), l.file().toString(), null, Status.ERROR, msg.toString(),
                List.of(), List.of(), null, 0, 0, 0, 0, 0, null, -1, null, List.of(), null);
    }
}
