package org.emini.harness.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.emini.harness.closedform.ClosedForms;
import org.emini.harness.load.Limits;
import org.emini.harness.load.ScenarioFiles;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.oracle.CompareReport;
import org.emini.harness.oracle.CompareStatus;
import org.emini.harness.oracle.Comparison;
import org.emini.harness.oracle.OracleEnvironment;
import org.emini.harness.oracle.OracleRunner;
import org.emini.harness.oracle.OracleScene;
import org.emini.harness.oracle.OracleSettings;
import org.emini.harness.oracle.TraceReader;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.Status;
import org.emini.harness.run.Trace;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code compare PATHS}: runs each scene in the engine and in the pymunk oracle (oracle-py/), compares
 * energy, momentum, penetration and (for scenes that are not chaotic) trajectories under the scene's
 * tolerances, and both with the closed form or law where the scene has one. Writes compare.json,
 * summary.md and both traces. Exits 1 only when a scene could not be compared (an oracle error,
 * traces that do not line up): differences between the engines are findings, not failures.
 */
@Command(name = "compare", mixinStandardHelpOptions = true,
        description = "Runs scenes in the engine and in pymunk and compares them (and both with the closed form).")
final class CompareCommand implements Callable<Integer> {
    @Mixin
    Library library;

    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "PATHS", arity = "0..*", description = "Scene files or folders (default: the library).")
    List<Path> paths;

    @Option(names = "--reports", paramLabel = "DIR", defaultValue = "reports/compare",
            description = "Where compare.json, summary.md and traces/ go (default: ${DEFAULT-VALUE}).")
    Path reports;

    @Option(names = "--jobs", paramLabel = "N", description = "Scenes run in parallel on each side (default: the number of cores).")
    Integer jobs;

    @Mixin
    OracleOptions oracleOptions;

    @Option(names = "-k", paramLabel = "PATTERN",
            description = "Only the scenes whose id matches: a glob (closed-form/*) or a substring; repeat for several.")
    List<String> patterns;

    @Option(names = "--setup-only", description = "Create or refresh the oracle's environment, then stop.")
    boolean setupOnly;

    @Override
    public Integer call() throws Exception {
        long start = System.nanoTime();
        Path oracleHome = oracleOptions.home(library);
        OracleEnvironment env = oracleOptions.environment(library);
        Path interpreter = env.ensure(System.err);
        if (setupOnly) {
            System.out.println("oracle environment ready: " + interpreter);
            return 0;
        }
        List<ScenarioLoader.Loaded> loaded = SceneFilter.keep(spec, SceneBatch.load(library.loader(),
                scenesForTheOracle(library.files(spec, paths))), patterns);
        List<Path> valid = new ArrayList<>();
        for (ScenarioLoader.Loaded l : loaded) {
            if (l.ok()) {
                valid.add(l.file());
            }
        }
        int threads = jobs != null ? Options.atLeast(spec, "--jobs", jobs, 1) : Runtime.getRuntime().availableProcessors();
        Path oracleTraces = reports.resolve("traces").resolve("pymunk");
        Path engineTraces = reports.resolve("traces").resolve("emini");
        OracleRunner.Run oracleRun = valid.isEmpty() ? null
            : new OracleRunner(interpreter, library.schemaFile()).start(valid, oracleTraces, threads);

        // The engine runs while the oracle does.
        try (SceneBatch engine = new SceneBatch(loaded, threads,
                new SceneBatch.Settings(engineTraces, true, true, Limits.SCENE_SECONDS, n -> { }))) {
            Map<Path, OracleScene> oracle = oracleRun == null ? Map.of() : oracleRun.await();
            List<Comparison.Scene> scenes = new ArrayList<>();
            int width = 10;
            for (ScenarioLoader.Loaded l : loaded) {
                width = Math.max(width, l.ok() ? l.scenario().name().length() : l.file().toString().length());
            }
            for (ScenarioLoader.Loaded l : loaded) {
                Comparison.Scene c;
                if (!l.ok()) {
                    c = new Comparison.Scene(l.file().toString(), l.file().toString(), null, CompareStatus.ERROR,
                            "invalid scene: " + l.problems(), Status.ERROR.label(), null, OracleSettings.DEFAULT, null,
                            List.of());
                } else {
                    SceneResult r = engine.result(l);
                    OracleScene o = oracle.get(l.file().toAbsolutePath().normalize());
                    Trace oracleTrace = o != null && o.ok() ? TraceReader.read(Path.of(o.trace())).trace() : null;
                    c = Comparison.compare(l.scenario(), r.status().label() + (r.message().isEmpty() ? "" : ": "
                            + r.message()), r.trace(), o, oracleTrace, ClosedForms.of(l.scenario()));
                }
                scenes.add(c);
                System.out.println(line(c, width));
            }
            CompareReport.Summary summary = CompareReport.Summary.of(scenes, (System.nanoTime() - start) / 1e9);
            System.out.println(summary);
            String command = "./emini harness " + String.join(" ", spec.commandLine().getParseResult().originalArgs());
            CompareReport.write(reports, scenes, summary, command, pymunkVersion(oracleHome));
            System.out.println("report: " + reports.resolve("summary.md") + ", " + reports.resolve("compare.json"));
            return summary.failed() ? 1 : 0;
        }
    }

    private static String pymunkVersion(Path oracleHome) {
        try {
            for (String line : Files.readAllLines(oracleHome.resolve("requirements.txt"), StandardCharsets.UTF_8)) {
                if (line.startsWith("pymunk==")) {
                    return "pymunk " + line.substring("pymunk==".length()).trim();
                }
            }
        } catch (IOException e) {
            // fall through
        }
        return "pymunk";
    }

    private static String line(Comparison.Scene c, int width) {
        CompareReport.Summary n = CompareReport.Summary.of(List.of(c), 0);
        String counts = String.format(Locale.ROOT, "%3d rows: %2d agree %2d differ; closer: engine %d, pymunk %d, tie %d",
                c.rows().size(), n.agree(), n.differ(), n.engineCloser(), n.oracleCloser(), n.ties());
        String line = String.format(Locale.ROOT, "%-12s %-" + width + "s %s", c.status().label(), c.scene(), counts);
        return c.note().isEmpty() ? line : line + "  [" + c.note() + "]";
    }

    /**
     * The oracle reads scene files itself, so each original world file becomes the scene
     * {@code convert} writes, under the reports folder ({@code converted/}); other files stay.
     */
    private List<Path> scenesForTheOracle(List<Path> files) throws IOException {
        List<Path> out = new ArrayList<>();
        for (Path f : files) {
            if (!ScenarioFiles.isWorldFile(f) || !Files.isRegularFile(f)) {
                out.add(f);
                continue;
            }
            String name = f.getFileName().toString();
            Path scene = reports.resolve("converted").resolve(name.substring(0, name.lastIndexOf('.')) + ".yaml");
            try {
                String yaml = ScenarioLoader.worldFileScene(f);
                Files.createDirectories(scene.getParent());
                Files.writeString(scene, yaml);
                out.add(scene);
            } catch (IOException e) {
                out.add(f); // the loader reports the file's problem in its row
            }
        }
        return out;
    }
}
