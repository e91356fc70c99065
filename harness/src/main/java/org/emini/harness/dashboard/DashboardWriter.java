package org.emini.harness.dashboard;

import com.google.gson.Gson;
import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.run.ReplayRecorder;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.ShapeSpec;
import org.emini.harness.sweep.PointStore;
import org.emini.harness.sweep.StabilityMapImage;
import org.emini.harness.sweep.SweepPoint;
import org.emini.harness.sweep.WorkPrecisionPlots;

/**
 * Writes the static dashboard: {@code reports/index.html} (the page, from this package's resource) and
 * {@code reports/dashboard/} ({@code data.js} with the verdicts, comparison, sweep points, stability
 * maps and the speed benchmark's summary ({@link BenchSummary}); {@code replay/*.js} with each scene's shapes and the engine's and oracle's traces, thinned to at
 * most {@link #MAX_FRAMES} frames). Everything is loaded by {@code <script>} tags, so the page opens
 * from the file system with no server and no network.
 */
public final class DashboardWriter {
    /** Frames kept per replay. */
    public static final int MAX_FRAMES = ReplayRecorder.MAX_FRAMES;
    /** Scenes with more recorded bodies than this get no replay (their data would be megabytes). */
    public static final int MAX_BODIES = ReplayRecorder.MAX_BODIES;

    private final Path reports;
    private final ScenarioLoader loader;
    private final Path libraryRoot;

    /**
     * @param reports the reports folder ({@code results.json}, {@code traces/}, {@code compare/},
     *     {@code sweep/}, {@code stability/}, {@code bench/} as the commands left them)
     * @param loader reads scene files (for the shapes a replay draws)
     * @param libraryRoot the scenarios folder (scene files in results.json are relative to the working directory)
     */
    public DashboardWriter(Path reports, ScenarioLoader loader, Path libraryRoot) {
        this.reports = reports;
        this.loader = loader;
        this.libraryRoot = libraryRoot;
    }

    /** Writes the page and its data; returns the index file. */
    public Path write() throws IOException {
        Path dash = reports.resolve("dashboard");
        Path replayDir = dash.resolve("replay");
        Files.createDirectories(replayDir);
        JsonObject data = new JsonObject();
        JsonObject results = readJson(reports.resolve("results.json"));
        data.add("results", results);
        data.add("sleeping", variantRun(readJson(reports.resolve("sleeping").resolve("results.json"))));
        data.add("nudged", nudgedRuns(reports.resolve("nudged")));
        data.add("workers", variantRun(readJson(reports.resolve("workers").resolve("x2").resolve("results.json"))));
        data.add("compare", readJson(reports.resolve("compare").resolve("compare.json")));
        JsonObject stability = readJson(reports.resolve("stability").resolve("stability.json"));
        if (stability != null && stability.has("families")) {
            // Map images are relative to the stability folder; the page is one folder up. Keep those that exist.
            for (JsonElement f : stability.getAsJsonArray("families")) {
                JsonObject fam = f.getAsJsonObject();
                if (fam.has("image")) {
                    String image = fam.get("image").getAsString();
                    if (Files.isRegularFile(reports.resolve("stability").resolve(image))) {
                        fam.addProperty("image", "stability/" + image);
                    } else {
                        fam.remove("image");
                    }
                }
            }
        }
        data.add("stability", stability);
        JsonObject styles = new JsonObject();
        for (String verdict : List.of("stable", "energy error", "energy growth", "NaN", "tunnelling", "penetration",
                "collapse", "error", "unsupported", "not run")) {
            String[] st = StabilityMapImage.style(verdict);
            JsonArray a = new JsonArray();
            a.add(st[0]);
            a.add(st[1]);
            styles.add(verdict, a);
        }
        data.add("stabilityStyles", styles);
        data.add("bench", BenchSummary.read(reports, libraryRoot.getParent().resolve("bench").resolve("results")));
        List<SweepPoint> points = PointStore.loadAll(reports.resolve("sweep"));
        JsonArray pts = new JsonArray();
        JsonObject plots = new JsonObject();
        Gson gson = new Gson();
        for (SweepPoint p : points) {
            pts.add(JsonParser.parseString(PointStore.json(p)));
            String stem = WorkPrecisionPlots.stem(p.scene());
            if (!plots.has(p.scene())) {
                JsonArray files = new JsonArray();
                for (String kind : List.of("error", "final", "energy", "momentum")) {
                    Path f = reports.resolve("sweep").resolve("plots").resolve(stem + "-" + kind + ".svg");
                    if (Files.isRegularFile(f)) {
                        files.add("sweep/plots/" + f.getFileName());
                    }
                }
                plots.add(p.scene(), files);
            }
        }
        data.add("sweep", pts);
        data.add("plots", plots);
        JsonArray replays = new JsonArray();
        if (results != null) {
            int n = 0;
            for (JsonElement e : results.getAsJsonArray("scenes")) {
                JsonObject s = e.getAsJsonObject();
                String id = s.get("scene").getAsString();
                if (!s.has("trace")) {
                    continue;
                }
                JsonObject replay = replay(id, s.get("file").getAsString(), reports.resolve(s.get("trace").getAsString()));
                if (replay == null) {
                    continue;
                }
                String file = "replay/r" + (n++) + ".js";
                Files.writeString(dash.resolve(file), "window.EMINI_REPLAY=window.EMINI_REPLAY||{};window.EMINI_REPLAY["
                        + gson.toJson(id) + "]=" + replay + ";\n", StandardCharsets.UTF_8);
                JsonObject entry = new JsonObject();
                entry.addProperty("scene", id);
                entry.addProperty("file", "dashboard/" + file);
                entry.addProperty("oracle", replay.has("oracle"));
                entry.addProperty("sleeping", replay.getAsJsonObject("engine").has("sleeping"));
                JsonObject eng = replay.getAsJsonObject("engine");
                entry.addProperty("landscape", eng.has("landscape") && eng.getAsJsonArray("landscape").size() > 0);
                replays.add(entry);
            }
        }
        data.add("replays", replays);
        // The World Designer's page (designer/, built by ./emini designer or ./emini test) replays these too.
        data.addProperty("designer", libraryRoot.toAbsolutePath().getParent().resolve("designer/target/page/index.html").toUri().toString());
        Files.writeString(dash.resolve("data.js"), "window.EMINI=" + data + ";\n", StandardCharsets.UTF_8);
        Path index = reports.resolve("index.html");
        try (InputStream in = DashboardWriter.class.getResourceAsStream("index.html")) {
            Files.write(index, in.readAllBytes());
        }
        return index;
    }

    private JsonObject replay(String id, String sceneFile, Path trace) throws IOException {
        if (!Files.isRegularFile(trace)) {
            return null;
        }
        Path file = Path.of(sceneFile);
        if (!Files.isRegularFile(file)) {
            file = libraryRoot.getParent().resolve(sceneFile);
        }
        ScenarioLoader.Loaded l = Files.isRegularFile(file) ? loader.load(file) : null;
        if (l == null || !l.ok()) {
            return null;
        }
        // The run's replay (every body, joints, particles, landscape) when it wrote one; else the trace.
        String name = trace.getFileName().toString();
        JsonObject recorded = name.endsWith(".trace.json")
                ? readJson(trace.resolveSibling(name.substring(0, name.length() - ".trace.json".length()) + ".replay.json"))
                : null;
        JsonObject engine = recorded != null ? recorded : readJson(trace);
        if (engine == null || engine.getAsJsonObject("bodies").size() > MAX_BODIES) {
            return null;
        }
        Scenario s = l.scenario();
        JsonObject out = new JsonObject();
        out.addProperty("scene", id);
        JsonObject shapes = new JsonObject();
        for (BodySpec b : s.bodies()) {
            JsonObject body = new JsonObject();
            body.add("shape", shape(b.shape()));
            body.addProperty("static", b.state().isStatic());
            body.addProperty("x", b.x());
            body.addProperty("y", b.y());
            body.addProperty("angle", b.state().angle());
            shapes.add(b.name(), body);
        }
        if (s.bodies().size() > 4 * MAX_BODIES) {
            return null;
        }
        out.add("bodies", shapes);
        out.add("engine", recorded != null ? recorded : thin(engine));
        out.addProperty("complete", recorded != null);
        Path oracle = reports.resolve("compare").resolve("traces").resolve("pymunk").resolve(id + ".trace.json");
        JsonObject o = readJson(oracle);
        if (o != null) {
            out.add("oracle", thin(o));
        }
        return out;
    }

    /**
     * A library run with one thing changed, beside the run as written: sleeping forced on
     * ({@code reports/sleeping/results.json}), a nudged speculative distance ({@code reports/nudged/}) or
     * two worker threads ({@code reports/workers/x2/}), all written by {@code ./emini run}. Its summary,
     * what was changed ({@code mode}, {@code nudge}, {@code workers}) and each scene's status, message, how
     * many bodies slept and state hash, or null when there is none.
     */
    static JsonObject variantRun(JsonObject results) {
        if (results == null || !results.has("scenes")) {
            return null;
        }
        JsonObject out = new JsonObject();
        out.add("generated", results.get("generated"));
        out.add("mode", results.get("sleeping"));
        out.add("nudge", results.get("nudge"));
        out.add("nudgeGravity", results.get("nudgeGravity"));
        out.add("workers", results.get("workers"));
        out.add("summary", results.get("summary"));
        JsonArray scenes = new JsonArray();
        for (JsonElement e : results.getAsJsonArray("scenes")) {
            JsonObject s = e.getAsJsonObject();
            JsonObject o = new JsonObject();
            o.add("scene", s.get("scene"));
            o.add("status", s.get("status"));
            o.add("message", s.get("message"));
            for (String key : new String[] {"mostAsleep", "stateHash"}) {
                if (s.has(key)) {
                    o.add(key, s.get(key));
                }
            }
            scenes.add(o);
        }
        out.add("scenes", scenes);
        return out;
    }

    /**
     * The nudged library runs ({@code reports/nudged/<name>/results.json}, one per factor, as
     * {@code ./emini run} writes them), smallest factor first; null when there are none.
     */
    static JsonArray nudgedRuns(Path folder) throws IOException {
        if (!Files.isDirectory(folder)) {
            return null;
        }
        List<Path> dirs;
        try (java.util.stream.Stream<Path> list = Files.list(folder)) {
            dirs = list.toList();
        }
        List<JsonObject> runs = new java.util.ArrayList<>();
        for (Path d : dirs) {
            JsonObject run = variantRun(readJson(d.resolve("results.json")));
            if (run != null && run.has("nudge") && !run.get("nudge").isJsonNull()) {
                runs.add(run);
            }
        }
        if (runs.isEmpty()) {
            return null;
        }
        runs.sort(java.util.Comparator.comparingDouble(r -> r.get("nudge").getAsDouble()));
        JsonArray out = new JsonArray();
        runs.forEach(out::add);
        return out;
    }

    /**
     * Keeps time, x, y, angle of each body, at most MAX_FRAMES samples, rounded; and, when the trace
     * says which bodies slept, {@code s} per body (1 while asleep) and {@code sleeping: true}.
     */
    static JsonObject thin(JsonObject trace) {
        JsonArray time = trace.getAsJsonArray("time");
        int n = time.size();
        int step = Math.max(1, (int) Math.ceil(n / (double) MAX_FRAMES));
        JsonObject out = new JsonObject();
        out.addProperty("source", trace.has("source") ? trace.get("source").getAsString() : "?");
        out.add("time", pick(time, step, 1000));
        JsonObject bodies = new JsonObject();
        for (Map.Entry<String, JsonElement> b : trace.getAsJsonObject("bodies").entrySet()) {
            JsonObject cols = b.getValue().getAsJsonObject();
            JsonObject c = new JsonObject();
            c.add("x", pick(cols.getAsJsonArray("x"), step, 100));
            c.add("y", pick(cols.getAsJsonArray("y"), step, 100));
            c.add("a", pick(cols.getAsJsonArray("angle"), step, 10000));
            if (cols.has("sleeping")) {
                c.add("s", pick(cols.getAsJsonArray("sleeping"), step, 1));
                out.addProperty("sleeping", true);
            }
            bodies.add(b.getKey(), c);
        }
        out.add("bodies", bodies);
        return out;
    }

    private static JsonArray pick(JsonArray a, int step, double scale) {
        JsonArray out = new JsonArray();
        for (int i = 0; i < a.size(); i += step) {
            add(out, a.get(i), scale);
        }
        if ((a.size() - 1) % step != 0) {
            add(out, a.get(a.size() - 1), scale);
        }
        return out;
    }

    private static void add(JsonArray out, JsonElement v, double scale) {
        if (v == null || v.isJsonNull()) {
            out.add((JsonElement) null);
        } else {
            out.add(Math.round(v.getAsDouble() * scale) / scale);
        }
    }

    static JsonObject shape(ShapeSpec s) {
        JsonObject o = new JsonObject();
        switch (s.kind()) {
            case circle -> {
                o.addProperty("kind", "circle");
                o.addProperty("r", s.radius());
            }
            case multiShape -> {
                o.addProperty("kind", "multi");
                JsonArray parts = new JsonArray();
                for (ShapeSpec.Part p : s.parts()) {
                    JsonObject part = shape(p.shape());
                    part.addProperty("ox", p.offsetX());
                    part.addProperty("oy", p.offsetY());
                    part.addProperty("oa", p.angle());
                    parts.add(part);
                }
                o.add("parts", parts);
            }
            default -> {
                o.addProperty("kind", "poly");
                JsonArray v = new JsonArray();
                if (s.kind() == ShapeSpec.Kind.rectangle) {
                    double w = s.width() / 2;
                    double h = s.height() / 2;
                    double[][] c = {{-w, -h}, {w, -h}, {w, h}, {-w, h}};
                    for (double[] p : c) {
                        v.add(pair(p[0], p[1]));
                    }
                } else if (s.kind() == ShapeSpec.Kind.regularPolygon) {
                    for (int i = 0; i < s.sides(); i++) {
                        double a = 2 * Math.PI * i / s.sides();
                        v.add(pair(s.radius() * Math.cos(a), s.radius() * Math.sin(a)));
                    }
                } else {
                    for (double[] p : s.vertices()) {
                        v.add(pair(p[0], p[1]));
                    }
                }
                o.add("v", v);
            }
        }
        return o;
    }

    private static JsonArray pair(double x, double y) {
        JsonArray a = new JsonArray();
        a.add(x);
        a.add(y);
        return a;
    }

    static JsonObject readJson(Path f) throws IOException {
        if (!Files.isRegularFile(f)) {
            return null;
        }
        return JsonParser.parseString(Files.readString(f, StandardCharsets.UTF_8)).getAsJsonObject();
    }
}
