package org.emini.bench.run;

import com.google.gson.GsonBuilder;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.emini.bench.engine.Engines;
import org.emini.bench.report.BenchReport;
import org.emini.bench.report.Charts;
import org.emini.bench.report.HtmlPage;
import org.emini.bench.report.MarkdownTables;
import org.emini.bench.scene.BenchScenes;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code ./emini bench}: runs the benchmark scenes in every engine with JMH, then the rain scaling
 * series, and publishes {@code bench.json}, {@code index.html} and the plots under the reports folder.
 */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Benchmarks Emini against dyn4j, JBox2D and libGDX's Box2D (JMH), pymunk, Box2D v3 and Rapier "
            + "(each in a process of its own) on the scenes of scenarios/bench and publishes JSON, an HTML page and plots "
            + "under reports/bench.")
public final class BenchMain implements Callable<Integer> {
    @Option(names = "--quick", description = "CI-sized run: short iterations in this JVM, short preroll, three scaling points.")
    boolean quick;

    @Option(names = "--reports", paramLabel = "DIR", description = "Output folder (default: reports/bench).")
    Path reports;

    @Option(names = "--scenes", split = ",", paramLabel = "ID", description = "Only these table scenes (ids like bench/pyramid-20).")
    List<String> onlyScenes;

    @Option(names = "--engines", split = ",", paramLabel = "ID",
            description = "Only these engines (default: all): emini, dyn4j, jbox2d, gdx-box2d, pymunk, box2d-v3, rapier.")
    List<String> engines;

    @Option(names = "--scaling", split = ",", paramLabel = "N", description = "Rain body counts of the scaling run (default: the mode's).")
    List<Integer> scaling;

    @Option(names = "--no-scaling", description = "Skip the scaling run.")
    boolean noScaling;

    @Option(names = "--resume", description = "Reuse the results a previous run kept in the reports folder (measurements/, finished JMH logs, "
        + "an out-of-process engine's ENGINE.json when it has every scene); run only what is missing.")
    boolean resume;

    @Option(names = "--scaling-cap", split = ",", paramLabel = "ENGINE=N",
            description = "Skip scaling points above N bodies for an engine (e.g. dyn4j=5000 where its preroll would take too long).")
    Map<String, Integer> scalingCap;

    @Option(names = "--render", description = "Run nothing: write the page, plots and RESULTS.md again from the reports folder's bench.json.")
    boolean render;

    @Option(names = "--add", split = ",", paramLabel = "ENGINE",
            description = "Run only these out-of-process engines (pymunk, box2d-v3, rapier) on the scenes of the reports folder's "
                + "bench.json and add them to the report (replacing their earlier figures).")
    List<String> add;

    /** Runs the command line and exits with its status. */
    public static void main(String[] args) {
        System.exit(new CommandLine(new BenchMain()).execute(args));
    }

    @Override
    public Integer call() throws IOException {
        System.setProperty("java.awt.headless", "true");
        long start = System.nanoTime();
        BenchScenes scenes = BenchScenes.open();
        BenchPlan.Mode mode = quick ? BenchPlan.QUICK : BenchPlan.FULL;
        Path out = reports != null ? reports : scenes.root().resolve("reports").resolve("bench");
        if (render || add != null) {
            BenchReport old = readReport(out);
            List<String> shown = new ArrayList<>(Engines.ALL);
            if (add != null) {
                known(add, ExternalBench.IDS);
                List<BenchReport.SceneEntry> table = new ArrayList<>();
                for (BenchReport.SceneEntry s : old.scenes()) {
                    List<Measurement> rs = new ArrayList<>(s.results());
                    rs.removeIf(m -> add.contains(m.engine()));
                    table.add(new BenchReport.SceneEntry(s.id(), s.title(), s.status(), s.message(), rs));
                }
                List<Measurement> scal = new ArrayList<>(old.scaling());
                List<String> scalingIds = scal.stream().map(Measurement::scene).distinct().toList();
                scal.removeIf(m -> add.contains(m.engine()));
                Map<String, Map<String, Object>> external = new LinkedHashMap<>(old.external());
                BenchPlan.Mode oldMode = "quick".equals(old.mode()) ? BenchPlan.QUICK : BenchPlan.FULL;
                for (String e : add) {
                    ExternalBench.Outcome o = ExternalBench.run(e, scenes, oldMode, out, externalScenes(table, scalingIds), false);
                    System.out.println(e + ": " + o.status() + ": " + o.message());
                    table = withExternal(table, o);
                    scal = scalingWithExternal(scal, o, scalingIds);
                    external.put(e, o.summary());
                }
                old = new BenchReport(old.format(), old.version(), old.generated(), old.mode(), old.jmh(), old.machine(),
                    old.loadAverageEnd(), old.seconds(), table, scal, external, old.resumed());
            }
            for (BenchReport.SceneEntry s : old.scenes()) {
                for (Measurement m : s.results()) {
                    if (!shown.contains(m.engine())) {
                        shown.add(m.engine());
                    }
                }
            }
            write(out, old, shown);
            System.out.println("wrote " + out.resolve("index.html"));
            return 0;
        }
        Path checks = out.resolve("checks");
        Path jmhLogs = out.resolve("jmh");
        Files.createDirectories(checks);
        Files.createDirectories(jmhLogs);
        List<String> all = new ArrayList<>(Engines.ALL);
        all.addAll(ExternalBench.IDS);
        if (engines != null) {
            known(engines, all);
        }
        // The JMH engines run here; the others after them, each in a process of its own.
        List<String> engineIds = new ArrayList<>(engines != null ? engines : Engines.ALL);
        engineIds.retainAll(Engines.ALL);
        List<String> externalIds = new ArrayList<>(ExternalBench.IDS);
        if (engines != null) {
            externalIds.retainAll(engines);
        }
        Map<String, Object> machine = Machine.describe();
        System.out.printf(Locale.ROOT, "bench (%s) on %s, %s cores, load average %.1f; reports in %s%n",
            mode.quick() ? "quick" : "full", machine.get("cpu"), machine.get("cores"), Machine.loadAverage(), out);
        BenchRunner runner = new BenchRunner(scenes, mode, checks, jmhLogs);
        boolean failed = false;
        boolean kept = false;

        List<BenchReport.SceneEntry> table = new ArrayList<>();
        for (BenchPlan.Scene s : BenchPlan.SCENES) {
            if (onlyScenes != null && !onlyScenes.contains(s.id())) {
                continue;
            }
            if (scenes.file(s.id()) == null) {
                String why = "no scene file yet; waits for " + s.needs();
                System.out.printf("%-28s pending: %s%n", s.id(), why);
                table.add(new BenchReport.SceneEntry(s.id(), s.title(), "pending", why, List.of()));
                continue;
            }
            List<Measurement> results = new ArrayList<>();
            for (String e : engineIds) {
                Measurement m = runner.measure(s.id(), e, resume);
                failed |= "error".equals(m.status());
                print(m);
                results.add(m);
            }
            table.add(new BenchReport.SceneEntry(s.id(), s.title(), "ran", "", results));
        }

        List<Measurement> scalingResults = new ArrayList<>();
        List<Integer> counts = noScaling ? List.of() : scaling != null ? scaling : quick ? BenchPlan.SCALING_QUICK : BenchPlan.SCALING;
        for (int n : counts) {
            for (String e : engineIds) {
                if (scalingCap != null && scalingCap.containsKey(e) && n > scalingCap.get(e)) {
                    Measurement skip = Measurement.notRun("bench/rain-" + n, e, "skipped",
                        "above --scaling-cap " + e + "=" + scalingCap.get(e));
                    print(skip);
                    scalingResults.add(skip);
                    continue;
                }
                Measurement m = runner.measure("bench/rain-" + n, e, resume);
                failed |= "error".equals(m.status());
                print(m);
                scalingResults.add(m);
            }
        }

        Map<String, Object> jmh = new LinkedHashMap<>();
        jmh.put("version", "1.37");
        jmh.put("mode", "AverageTime, one tick per operation");
        jmh.put("forks", mode.forks());
        jmh.put("warmup", mode.warmups() + " x " + mode.warmupMillis() + " ms");
        jmh.put("measurement", mode.iterations() + " x " + mode.iterationMillis() + " ms");
        jmh.put("preroll", mode.preroll() < 0 ? "the scene's run duration" : mode.preroll() + " ticks");
        jmh.put("profiler", "gc");
        // The out-of-process engines on the scenes that ran, at the same scaling points.
        List<String> shown = new ArrayList<>(engineIds);
        Map<String, Map<String, Object>> external = new LinkedHashMap<>();
        for (String e : externalIds) {
            List<String> scalingIds = new ArrayList<>();
            for (int n : counts) {
                if (scalingCap == null || !scalingCap.containsKey(e) || n <= scalingCap.get(e)) {
                    scalingIds.add("bench/rain-" + n);
                }
            }
            ExternalBench.Outcome o = ExternalBench.run(e, scenes, mode, out, externalScenes(table, scalingIds), resume);
            System.out.println(e + ": " + o.status() + ": " + o.message());
            external.put(e, o.summary());
            failed |= "error".equals(o.status());
            for (Measurement m : o.measurements()) {
                print(m);
                failed |= "error".equals(m.status());
            }
            kept |= o.kept();
            if (!o.measurements().isEmpty()) {
                shown.add(e);
                table = withExternal(table, o);
                scalingResults = scalingWithExternal(scalingResults, o, scalingIds);
            }
        }
        BenchReport report = new BenchReport("emini-bench", 1, Instant.now().truncatedTo(ChronoUnit.SECONDS).toString(),
            mode.quick() ? "quick" : "full", jmh, machine, Machine.loadAverage(), (System.nanoTime() - start) / 1e9,
            table, scalingResults, external, runner.reused() > 0 || kept);
        write(out, report, shown);
        System.out.printf(Locale.ROOT, "wrote %s and %s (%.0f s)%n", out.resolve("bench.json"), out.resolve("index.html"), report.seconds());
        return failed ? 1 : 0;
    }

    /** Refuses engine ids not in {@code known}, naming them. */
    private static void known(List<String> ids, List<String> known) {
        for (String id : ids) {
            if (!known.contains(id)) {
                throw new CommandLine.ParameterException(new CommandLine(new BenchMain()), "unknown engine " + id + "; known: "
                    + String.join(", ", known));
            }
        }
    }

    /** The scenes an out-of-process engine is timed on: those of the table that ran, and the scaling points. */
    private static List<String> externalScenes(List<BenchReport.SceneEntry> table, List<String> scaling) {
        List<String> ids = new ArrayList<>();
        for (BenchReport.SceneEntry s : table) {
            if ("ran".equals(s.status())) {
                ids.add(s.id());
            }
        }
        for (String id : scaling) {
            if (!ids.contains(id)) {
                ids.add(id);
            }
        }
        return ids;
    }

    /** The table with an out-of-process engine's measurements added to their scenes. */
    private static List<BenchReport.SceneEntry> withExternal(List<BenchReport.SceneEntry> table, ExternalBench.Outcome o) {
        List<BenchReport.SceneEntry> merged = new ArrayList<>();
        for (BenchReport.SceneEntry s : table) {
            List<Measurement> rs = new ArrayList<>(s.results());
            for (Measurement m : o.measurements()) {
                if (m.scene().equals(s.id())) {
                    rs.add(m);
                }
            }
            merged.add(new BenchReport.SceneEntry(s.id(), s.title(), s.status(), s.message(), rs));
        }
        return merged;
    }

    /** The scaling series with an out-of-process engine's measurements of its scenes added. */
    private static List<Measurement> scalingWithExternal(List<Measurement> scaling, ExternalBench.Outcome o, List<String> scalingIds) {
        List<Measurement> out = new ArrayList<>(scaling);
        for (Measurement m : o.measurements()) {
            if (scalingIds.contains(m.scene())) {
                out.add(m);
            }
        }
        return out;
    }

    /** The bench.json of the reports folder (one from before Box2D v3 and Rapier keeps pymunk's status as "pymunk"). */
    private static BenchReport readReport(Path out) throws IOException {
        JsonObject json = JsonParser.parseString(Files.readString(out.resolve("bench.json"), StandardCharsets.UTF_8)).getAsJsonObject();
        if (!json.has("external")) {
            JsonObject external = new JsonObject();
            if (json.has("pymunk")) {
                external.add("pymunk", json.get("pymunk"));
            }
            json.add("external", external);
        }
        return new GsonBuilder().serializeSpecialFloatingPointValues().create().fromJson(json, BenchReport.class);
    }

    /** Writes bench.json, the plots, index.html and RESULTS.md (the tables in Markdown). */
    static void write(Path out, BenchReport report, List<String> engineIds) throws IOException {
        Files.createDirectories(out);
        Files.writeString(out.resolve("bench.json"),
            new GsonBuilder().setPrettyPrinting().serializeNulls().serializeSpecialFloatingPointValues().create().toJson(report),
            StandardCharsets.UTF_8);
        String scenesChart = Charts.sceneTimes(out, report.scenes(), engineIds);
        String scalingChart = Charts.scaling(out, report.scaling(), engineIds);
        Files.writeString(out.resolve("index.html"), HtmlPage.render(report, engineIds, scenesChart, scalingChart), StandardCharsets.UTF_8);
        Files.writeString(out.resolve("RESULTS.md"), MarkdownTables.render(report, engineIds), StandardCharsets.UTF_8);
    }

    private static void print(Measurement m) {
        if (!"ok".equals(m.status())) {
            System.out.printf("%-28s %-10s %s: %s%n", m.scene(), m.engine(), m.status(), m.message());
            return;
        }
        // The out-of-process engines have no allocation figure.
        String bytes = m.threadBytesPerTick() == null ? "—" : String.format(Locale.ROOT, "%.0f", m.threadBytesPerTick());
        System.out.printf(Locale.ROOT, "%-28s %-10s %9.3f ms/tick cpu  %9.3f wall  %8.2f us/body  %10s B/tick  %s%n",
            m.scene(), m.engine(), m.cpuMsPerTick() == null ? Double.NaN : m.cpuMsPerTick(), m.msPerTick(), m.usPerBody(),
            bytes, m.verdict());
    }
}
