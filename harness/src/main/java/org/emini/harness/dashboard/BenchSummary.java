package org.emini.harness.dashboard;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.emini.harness.report.LogLogSlope;

/**
 * What the dashboard shows of the speed benchmark ({@code ./emini bench}, which writes
 * {@code REPORTS/bench/bench.json}): per scene and engine the CPU time per tick, the benchmark
 * thread's allocation per tick and the scene check's verdict; the scaling series with each engine's
 * log-log slope; the machine and load it was measured under; and the benchmark's own page and plots
 * when present.
 * Read as plain JSON: the harness does not depend on the benchmark module, which depends on it.
 */
final class BenchSummary {
    private BenchSummary() {
    }

    /**
     * The summary of {@code reports/bench/bench.json}, or null when there is none.
     *
     * @throws IOException if the file exists but cannot be read or is not a benchmark report
     */
    static JsonObject read(Path reports) throws IOException {
        return read(reports, (Path) null);
    }

    /**
     * The summary of {@code reports/bench/bench.json}; without one, of the published run
     * ({@code published}, the repository's {@code bench/results/}, marked {@code published} with the
     * file's path); null when neither exists.
     *
     * @param published the folder of the published run, or null
     * @throws IOException if the file exists but cannot be read or is not a benchmark report
     */
    static JsonObject read(Path reports, Path published) throws IOException {
        Path dir = reports.resolve("bench");
        JsonObject own = readFolder(dir, "bench/");
        if (own != null || published == null || !Files.isRegularFile(published.resolve("bench.json"))) {
            return own;
        }
        String link = reports.toAbsolutePath().normalize().relativize(published.toAbsolutePath().normalize())
                .toString().replace('\\', '/') + "/";
        JsonObject out = readFolder(published, link);
        out.addProperty("published", link + "bench.json");
        return out;
    }

    private static JsonObject readFolder(Path dir, String link) throws IOException {
        Path file = dir.resolve("bench.json");
        JsonObject bench;
        try {
            bench = DashboardWriter.readJson(file);
        } catch (JsonParseException | IllegalStateException x) {
            throw new IOException(file + ": not valid JSON: " + x.getMessage(), x);
        }
        if (bench == null) {
            return null;
        }
        if (!bench.has("format") || !"emini-bench".equals(bench.get("format").getAsString())) {
            throw new IOException(file + ": not a benchmark report (format is not emini-bench)");
        }
        JsonObject out = new JsonObject();
        copy(bench, out, "generated");
        copy(bench, out, "mode");
        copy(bench, out, "resumed");
        copy(bench, out, "loadAverageEnd");
        JsonObject machine = bench.getAsJsonObject("machine");
        if (machine != null) {
            out.add("machine", machine.deepCopy());
        }
        Set<String> engines = new LinkedHashSet<>();
        JsonArray scenes = new JsonArray();
        for (JsonElement e : array(bench, "scenes")) {
            JsonObject s = e.getAsJsonObject();
            JsonObject row = new JsonObject();
            copy(s, row, "id");
            copy(s, row, "title");
            copy(s, row, "status");
            copy(s, row, "message");
            JsonObject cells = new JsonObject();
            for (JsonElement r : array(s, "results")) {
                JsonObject m = r.getAsJsonObject();
                String engine = m.get("engine").getAsString();
                engines.add(engine);
                cells.add(engine, cell(m));
            }
            row.add("results", cells);
            scenes.add(row);
        }
        out.add("scenes", scenes);
        Map<String, JsonArray> points = new LinkedHashMap<>();
        for (JsonElement e : array(bench, "scaling")) {
            JsonObject m = e.getAsJsonObject();
            Double cost = cost(m);
            if (cost == null || !m.has("dynamicBodies")) {
                continue;
            }
            String engine = m.get("engine").getAsString();
            double bodies = m.get("dynamicBodies").getAsDouble();
            JsonArray p = new JsonArray();
            p.add(bodies);
            p.add(cost);
            points.computeIfAbsent(engine, k -> new JsonArray()).add(p);
            engines.add(engine);
        }
        JsonObject scaling = new JsonObject();
        for (Map.Entry<String, JsonArray> en : points.entrySet()) {
            LogLogSlope fit = new LogLogSlope();
            for (JsonElement p : en.getValue()) {
                fit.add(p.getAsJsonArray().get(0).getAsDouble(), p.getAsJsonArray().get(1).getAsDouble());
            }
            JsonObject s = new JsonObject();
            s.add("points", en.getValue());
            Double slope = fit.slope();
            if (slope != null) {
                s.addProperty("slope", slope);
            }
            scaling.add(en.getKey(), s);
        }
        out.add("scaling", scaling);
        JsonArray ids = new JsonArray();
        engines.forEach(ids::add);
        out.add("engines", ids);
        // Links are relative to the dashboard (REPORTS/index.html); only files that exist.
        if (Files.isRegularFile(dir.resolve("index.html"))) {
            out.addProperty("page", link + "index.html");
        }
        JsonArray images = new JsonArray();
        // The scaling plot only: the page draws the per-scene bars itself (its legend beside the bars).
        for (String name : List.of("scaling.svg", "scaling.png")) {
            if (Files.isRegularFile(dir.resolve(name)) && images.isEmpty()) {
                images.add(link + name);
            }
        }
        out.add("images", images);
        return out;
    }

    private static JsonObject cell(JsonObject m) {
        JsonObject c = new JsonObject();
        copy(m, c, "status");
        copy(m, c, "message");
        Double cost = cost(m);
        if (cost != null) {
            c.addProperty("cpuMsPerTick", cost);
        }
        copy(m, c, "threadBytesPerTick");
        JsonObject check = m.has("check") && m.get("check").isJsonObject() ? m.getAsJsonObject("check") : null;
        if (check != null && check.has("verdict")) {
            c.add("verdict", check.get("verdict"));
        }
        return c;
    }

    /** CPU ms per tick where measured, else wall ms per tick (as the benchmark's own tables). */
    private static Double cost(JsonObject m) {
        for (String k : List.of("cpuMsPerTick", "msPerTick")) {
            if (m.has(k) && m.get(k).isJsonPrimitive() && m.get(k).getAsJsonPrimitive().isNumber()) {
                return m.get(k).getAsDouble();
            }
        }
        return null;
    }

    private static JsonArray array(JsonObject o, String key) {
        return o.has(key) && o.get(key).isJsonArray() ? o.getAsJsonArray(key) : new JsonArray();
    }

    private static void copy(JsonObject from, JsonObject to, String key) {
        if (from.has(key) && !from.get(key).isJsonNull()) {
            to.add(key, from.get(key).deepCopy());
        }
    }
}
