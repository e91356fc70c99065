package org.emini.harness.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.LongConsumer;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import org.emini.harness.load.Problem;
import org.emini.harness.load.ScenarioFiles;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.report.ConsoleTable;
import org.emini.harness.report.JUnitXmlWriter;
import org.emini.harness.report.ResultsWriter;
import org.emini.harness.report.Summary;
import org.emini.harness.report.TraceWriter;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.Status;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code run PATHS}: runs scenes, prints one line per scene and a summary, writes results.json, JUnit
 * XML and traces under the reports folder. Exits 1 when a scene regresses or errs.
 */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = "Runs scenario files (or folders of them) and writes the report.")
final class RunCommand implements Callable<Integer> {
    @Mixin
    Library library;

    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "PATHS", arity = "0..*", description = "Scene files or folders (default: the library).")
    List<Path> paths;

    @Option(names = "--reports", paramLabel = "DIR", defaultValue = "reports",
            description = "Where results.json, junit/ and traces/ go (default: ${DEFAULT-VALUE}).")
    Path reports;

    @Option(names = "--no-traces", description = "Do not write traces.")
    boolean noTraces;

    @Option(names = "--jobs", paramLabel = "N", description = "Scenes run in parallel (default: the number of cores).")
    Integer jobs;

    @Option(names = "--scene-timeout", paramLabel = "SECONDS", defaultValue = "1800",
            description = "Wall-clock time a scene may run before it stops as ERROR (default: ${DEFAULT-VALUE}).")
    double sceneTimeout;

    @Option(names = "--progress", negatable = true,
            description = "Show a progress bar (default: when the output is a terminal).")
    Boolean progress;

    @Override
    public Integer call() throws Exception {
        long start = System.nanoTime();
        if (jobs != null) {
            Options.atLeast(spec, "--jobs", jobs, 1);
        }
        Options.require(spec, sceneTimeout > 0, "--scene-timeout must be > 0, was " + sceneTimeout);
        // Made first, so that reports under a file fail now, not after the run.
        Files.createDirectories(reports);
        ScenarioLoader loader = library.loader();
        List<Path> files = library.files(spec, paths);
        List<ScenarioLoader.Loaded> loaded = new ArrayList<>();
        long totalTicks = 0;
        int width = 10;
        for (Path f : files) {
            ScenarioLoader.Loaded l = loader.load(f);
            loaded.add(l);
            if (l.ok()) {
                totalTicks += l.scenario().ticks();
                width = Math.max(width, l.scenario().name().length());
            }
        }
        Path traces = noTraces ? null : reports.resolve("traces");
        boolean bar = progress != null ? progress : System.console() != null;
        int threads = jobs != null ? jobs : Runtime.getRuntime().availableProcessors();
        List<SceneResult> results = new ArrayList<>();
        ExecutorService pool = Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "scene");
            t.setDaemon(true);
            return t;
        });
        try (ProgressBar pb = bar ? new ProgressBarBuilder().setTaskName("ticks").setInitialMax(totalTicks)
                .setConsumer(new ConsoleProgressBarConsumer(System.err)).setUpdateIntervalMillis(250).build() : null) {
            LongConsumer ticks = pb == null ? n -> { } : pb::stepBy;
            List<Future<SceneResult>> futures = new ArrayList<>();
            for (ScenarioLoader.Loaded l : loaded) {
                futures.add(pool.submit(() -> finish(l, ticks, traces, sceneTimeout)));
            }
            for (Future<SceneResult> f : futures) {
                SceneResult r = get(f);
                results.add(r);
                System.out.println((bar ? "\r\033[K" : "") + ConsoleTable.line(r, width));
            }
        } finally {
            pool.shutdownNow();
        }
        Summary summary = Summary.of(results, (System.nanoTime() - start) / 1e9);
        System.out.println(summary);
        ResultsWriter.write(reports.resolve("results.json"), results, summary, traces);
        JUnitXmlWriter.write(reports.resolve("junit").resolve("TEST-scenarios.xml"), results, summary);
        StringBuilder text = new StringBuilder();
        for (SceneResult r : results) {
            text.append(ConsoleTable.line(r, width)).append('\n');
        }
        text.append(summary).append('\n');
        Files.writeString(reports.resolve("summary.txt"), text, StandardCharsets.UTF_8);
        return summary.failed() ? 1 : 0;
    }

    /** Runs one loaded scene (or reports why it cannot), writes its trace and drops it from memory. */
    private static SceneResult finish(ScenarioLoader.Loaded l, LongConsumer ticks, Path traces, double timeout) {
        if (!l.ok()) {
            StringBuilder msg = new StringBuilder("invalid scene:");
            for (Problem p : l.problems()) {
                msg.append("\n    ").append(p);
            }
            return new SceneResult(l.file().toString(), l.file().toString(), null, Status.ERROR, msg.toString(),
                    List.of(), List.of(), null, 0, 0, 0, 0, 0, null);
        }
        SceneResult r = ScenarioRunner.run(l.scenario(), ticks, timeout);
        if (traces != null && r.trace() != null && l.scenario().run().record().trace()) {
            try {
                TraceWriter.write(TraceWriter.fileFor(traces, r.scene()), r.scene(), "emini", r.trace());
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return r.withoutTrace();
    }

    private static SceneResult get(Future<SceneResult> f) throws IOException, InterruptedException {
        try {
            return f.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof UncheckedIOException io) {
                throw io.getCause();
            }
            throw new IllegalStateException(e.getCause());
        }
    }
}
