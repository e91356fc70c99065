package org.emini.harness.cli;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.report.ConsoleTable;
import org.emini.harness.report.JUnitXmlWriter;
import org.emini.harness.report.ResultsWriter;
import org.emini.harness.report.Summary;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.Status;
import org.emini.harness.scenario.Scenario;
import org.emini.world.World;
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

    /** {@code --sleeping}: every scene's world.sleeping forced on or off, or as each scene says. */
    enum Sleeping { on, off, scene }

    @Option(names = "--sleeping", paramLabel = "on|off|scene", defaultValue = "scene",
            description = "Force sleeping on or off in every scene, keeping the tolerances a scene gives "
                    + "(default: ${DEFAULT-VALUE}, as each scene's world.sleeping says). ./emini run runs the "
                    + "library with sleeping on as well as off.")
    Sleeping sleeping;

    @Option(names = "--scale", paramLabel = "K",
            description = "Run every scene at K times its size: lengths, speeds, gravity and the engine's length "
                    + "scale times K, each bound times K to the power of its unit's length (harness/README.md, "
                    + "Scaled runs). ./emini run runs the stacking and fast-body scenes at 0.025 and 25.")
    Double scale;

    @Option(names = "--nudge", paramLabel = "F",
            description = "Run every scene with the engine's speculative distance times F (the scene's own or the "
                    + "default 0.5 px) and gravity times 1 + (F - 1) / 10,000: with F = 0.98 or 1.02 a verdict that "
                    + "flips was reached by the round-off's luck, not by a margin (harness/README.md, Nudged runs).")
    Double nudge;

    @Option(names = "--workers", paramLabel = "N", defaultValue = "1",
            description = "Threads each scene's world shares its ticks among (World.setWorkerCount), 1 to "
                    + World.MAX_WORKERS + " (default: ${DEFAULT-VALUE}). The engine promises the same bits for any "
                    + "count: diff --same-state against a run at 1 proves it; every shared loop is split, so small worlds share too "
                    + "(World.setSplitAlways; slower, not a speed figure; harness/README.md, Worker threads).")
    int workers;

    @Option(names = "-k", paramLabel = "PATTERN",
            description = "Only the scenes whose id matches: a glob (stacking/*, *-60hz) or a substring (pendulum); "
                    + "repeat for several.")
    List<String> patterns;

    @Option(names = "--fail-fast", description = "Stop at the first scene that is FAIL or ERROR (in file order); "
            + "the scenes after it are not run or reported.")
    boolean failFast;

    @Option(names = "--junit", paramLabel = "FILE",
            description = "Also write the JUnit XML report to FILE (it is always in REPORTS/junit/TEST-scenarios.xml).")
    Path junit;

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
        Options.within(spec, "--workers", workers, 1, World.MAX_WORKERS);
        // Made first, so that reports under a file fail now, not after the run.
        Files.createDirectories(reports);
        List<ScenarioLoader.Loaded> loaded = SceneFilter.keep(spec, SceneBatch.load(library.loader(),
                library.files(spec, paths)), patterns);
        if (sleeping != Sleeping.scene) {
            loaded = SceneBatch.withSleeping(loaded, sleeping == Sleeping.on);
        }
        if (scale != null) {
            Options.require(spec, scale > 0 && !scale.isInfinite(), "--scale must be finite and > 0, was " + scale);
            loaded = SceneBatch.scaled(loaded, scale);
        }
        if (nudge != null) {
            Options.require(spec, nudge > 0 && !nudge.isInfinite(), "--nudge must be finite and > 0, was " + nudge);
            loaded = SceneBatch.nudged(loaded, nudge);
        }
        long totalTicks = 0;
        int width = 10;
        for (ScenarioLoader.Loaded l : loaded) {
            if (l.ok()) {
                totalTicks += l.scenario().ticks();
                width = Math.max(width, l.scenario().name().length());
            }
        }
        Path traces = noTraces ? null : reports.resolve("traces");
        boolean bar = progress != null ? progress : System.console() != null;
        int threads = jobs != null ? jobs : Runtime.getRuntime().availableProcessors();
        List<SceneResult> results = new ArrayList<>();
        try (ProgressBar pb = bar ? new ProgressBarBuilder().setTaskName("ticks").setInitialMax(totalTicks)
                .setConsumer(new ConsoleProgressBarConsumer(System.err)).setUpdateIntervalMillis(250).build() : null;
             SceneBatch batch = new SceneBatch(loaded, threads, new SceneBatch.Settings(traces, false, false,
                     sceneTimeout, pb == null ? n -> { } : pb::stepBy, workers))) {
            for (ScenarioLoader.Loaded l : loaded) {
                SceneResult r = batch.result(l);
                results.add(r);
                System.out.println((bar ? "\r\033[K" : "") + ConsoleTable.line(r, width));
                if (failFast && (r.status() == Status.FAIL || r.status() == Status.ERROR)) {
                    int left = loaded.size() - results.size();
                    if (left > 0) {
                        System.out.println("--fail-fast: stopped at " + r.scene() + "; " + left + " scenes not run");
                    }
                    break;
                }
            }
        }
        Summary summary = Summary.of(results, (System.nanoTime() - start) / 1e9);
        System.out.println(summary);
        String slept = sleepingLine(results);
        if (slept != null) {
            System.out.println(slept);
        }
        String nudged = nudge == null ? null : "nudged: every scene's speculative distance times " + nudge
                + " and gravity times " + Scenario.gravityNudge(nudge);
        if (nudged != null) {
            System.out.println(nudged);
        }
        String shared = workers == 1 ? null : "workers: every scene's ticks shared among " + workers
                + " threads, every shared loop split (World.setSplitAlways; results.json, stateHash; diff --same-state against"
                + " a run at 1)";
        if (shared != null) {
            System.out.println(shared);
        }
        ResultsWriter.write(reports.resolve("results.json"), results, summary, traces,
                sleeping == Sleeping.scene ? null : sleeping.name(), nudge, workers);
        JUnitXmlWriter.write(reports.resolve("junit").resolve("TEST-scenarios.xml"), results, summary);
        if (junit != null) {
            JUnitXmlWriter.write(junit, results, summary);
        }
        StringBuilder text = new StringBuilder();
        for (SceneResult r : results) {
            text.append(ConsoleTable.line(r, width)).append('\n');
        }
        text.append(summary).append('\n');
        if (slept != null) {
            text.append(slept).append('\n');
        }
        if (nudged != null) {
            text.append(nudged).append('\n');
        }
        if (shared != null) {
            text.append(shared).append('\n');
        }
        Files.writeString(reports.resolve("summary.txt"), text, StandardCharsets.UTF_8);
        return summary.failed() ? 1 : 0;
    }

    /** With sleeping forced on: in how many scenes bodies fell asleep (a pass where none slept proves little). */
    private String sleepingLine(List<SceneResult> results) {
        if (sleeping != Sleeping.on) {
            return null;
        }
        int ran = 0;
        int slept = 0;
        for (SceneResult r : results) {
            if (r.mostAsleep() >= 0) {
                ran++;
                slept += r.mostAsleep() > 0 ? 1 : 0;
            }
        }
        return "sleeping on: bodies fell asleep in " + slept + " of the " + ran + " scenes that ran (results.json, mostAsleep)";
    }
}
