package org.emini.harness.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.emini.harness.closedform.ClosedForms;
import org.emini.harness.load.Limits;
import org.emini.harness.load.ScenarioFiles;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.oracle.CompareStatus;
import org.emini.harness.oracle.Comparison;
import org.emini.harness.oracle.MultiComparison;
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

    @Option(names = "--oracle", paramLabel = "NAME,...", split = ",", defaultValue = "pymunk,box2d",
            description = "The oracles: pymunk (Chipmunk 2D) and box2d (Box2D v3.1.1) (default: ${DEFAULT-VALUE}).")
    List<String> oracles;

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
        for (String o : oracles) {
            Options.require(spec, OracleOptions.ENGINES.contains(o), "--oracle: unknown oracle " + o + " (pymunk, box2d)");
        }
        Path engineTraces = reports.resolve("traces").resolve("emini");
        // Every oracle runs in a process of its own while the engine runs the same scenes.
        Map<String, OracleRunner.Run> runs = new LinkedHashMap<>();
        for (String o : oracles) {
            runs.put(o, valid.isEmpty() ? null : new OracleRunner(interpreter, library.schemaFile())
                    .start(valid, reports.resolve("traces").resolve(o), threads, o));
        }
        try (SceneBatch engine = new SceneBatch(loaded, threads,
                new SceneBatch.Settings(engineTraces, true, true, Limits.SCENE_SECONDS, n -> { }, 1))) {
            Map<String, Map<Path, OracleScene>> said = new LinkedHashMap<>();
            for (Map.Entry<String, OracleRunner.Run> r : runs.entrySet()) {
                said.put(r.getKey(), r.getValue() == null ? Map.of() : r.getValue().await());
            }
            List<MultiComparison.Scene> scenes = new ArrayList<>();
            int width = 10;
            for (ScenarioLoader.Loaded l : loaded) {
                width = Math.max(width, l.ok() ? l.scenario().name().length() : l.file().toString().length());
            }
            for (ScenarioLoader.Loaded l : loaded) {
                Map<String, Comparison.Scene> byOracle = new LinkedHashMap<>();
                for (String o : oracles) {
                    Comparison.Scene c;
                    if (!l.ok()) {
                        c = new Comparison.Scene(l.file().toString(), l.file().toString(), null, CompareStatus.ERROR,
                                "invalid scene: " + l.problems(), Status.ERROR.label(), null, OracleSettings.DEFAULT, null,
                                List.of());
                    } else {
                        SceneResult r = engine.result(l);
                        OracleScene os = said.get(o).get(l.file().toAbsolutePath().normalize());
                        Trace oracleTrace = os != null && os.ok() ? TraceReader.read(Path.of(os.trace())).trace() : null;
                        c = Comparison.compare(l.scenario(), r.status().label() + (r.message().isEmpty() ? "" : ": "
                                + r.message()), r.trace(), os, oracleTrace, ClosedForms.of(l.scenario()), o);
                    }
                    byOracle.put(o, c);
                }
                MultiComparison.Scene m = MultiComparison.merge(byOracle);
                scenes.add(m);
                System.out.println(line(m, width));
            }
            MultiComparison.Summary summary = MultiComparison.Summary.of(scenes, oracles, (System.nanoTime() - start) / 1e9);
            System.out.println(summary);
            String command = "./emini harness " + String.join(" ", spec.commandLine().getParseResult().originalArgs());
            MultiComparison.write(reports, scenes, summary, command, oracles, versions(oracleHome, oracles));
            System.out.println("report: " + reports.resolve("summary.md") + ", " + reports.resolve("compare.json"));
            return summary.failed() ? 1 : 0;
        }
    }

    /** The oracles' versions as pinned in oracle-py/requirements.txt. */
    private static String versions(Path oracleHome, List<String> oracles) {
        List<String> out = new ArrayList<>();
        for (String o : oracles) {
            out.add(o.equals("box2d") ? "Box2D 3.1.1 (" + pinned(oracleHome, "pyb2d3") + ")" : pinned(oracleHome, "pymunk"));
        }
        return String.join(", ", out);
    }

    private static String pinned(Path oracleHome, String name) {
        try {
            for (String line : Files.readAllLines(oracleHome.resolve("requirements.txt"), StandardCharsets.UTF_8)) {
                if (line.startsWith(name + "==")) {
                    return name + " " + line.substring(name.length() + 2).trim();
                }
            }
        } catch (IOException e) {
            // fall through
        }
        return name;
    }

    private static String line(MultiComparison.Scene m, int width) {
        MultiComparison.Summary n = MultiComparison.Summary.of(List.of(m), List.copyOf(m.byOracle().keySet()), 0);
        StringBuilder counts = new StringBuilder(String.format(Locale.ROOT, "%3d rows:", m.rows().size()));
        m.byOracle().keySet().forEach(o -> counts.append(String.format(Locale.ROOT, " %s %d agree %d differ;", o,
                n.agree().get(o), n.differ().get(o))));
        counts.append(" closer:");
        n.closer().forEach((k, v) -> counts.append(' ').append(k).append(' ').append(v));
        String line = String.format(Locale.ROOT, "%-12s %-" + width + "s %s", m.status().label(), m.first().scene(), counts);
        StringBuilder notes = new StringBuilder();
        m.byOracle().forEach((o, c) -> {
            if (!c.note().isEmpty()) {
                notes.append(notes.length() == 0 ? "" : "; ").append(c.note());
            }
        });
        return notes.length() == 0 ? line : line + "  [" + notes + "]";
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
