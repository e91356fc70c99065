package org.emini.harness.flavour;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import org.emini.harness.sweep.PointStore;
import org.emini.harness.sweep.SweepPoint;

/**
 * The float engine and its double-precision flavour side by side (issue 19): each comparison row with a
 * reference (the truth) in both flavours' compare.json, with pymunk's error beside them, and each sweep
 * point both flavours ran, with the error and the CPU cost of each and the cost ratio double / float.
 */
public final class FlavourReport {
    private FlavourReport() {
    }

    /**
     * Writes the report.
     *
     * @param floatCompare the float engine's compare folder (with compare.json), or null
     * @param doubleCompare the double flavour's compare folder, or null
     * @param sweep a sweep folder holding both flavours' points (engines emini and emini-double), or null
     * @return the Markdown text
     * @throws IOException when a file cannot be read
     */
    public static String markdown(Path floatCompare, Path doubleCompare, Path sweep) throws IOException {
        StringBuilder md = new StringBuilder("# The float engine and its double flavour\n\n");
        if (floatCompare != null && doubleCompare != null) {
            compare(md, rows(floatCompare), rows(doubleCompare));
        }
        if (sweep != null) {
            sweep(md, PointStore.loadAll(sweep));
        }
        return md.toString();
    }

    private static Map<String, JsonObject> rows(Path dir) throws IOException {
        Path file = dir.resolve("compare.json");
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException("flavours: no " + file + " (run compare first)");
        }
        JsonObject root = JsonParser.parseString(Files.readString(file, StandardCharsets.UTF_8)).getAsJsonObject();
        Map<String, JsonObject> out = new TreeMap<>();
        for (JsonElement s : root.getAsJsonArray("scenes")) {
            JsonObject scene = s.getAsJsonObject();
            if (!scene.has("rows")) {
                continue;
            }
            for (JsonElement r : scene.getAsJsonArray("rows")) {
                JsonObject row = r.getAsJsonObject();
                if (!number(row, "reference").isNaN()) {
                    out.put(scene.get("scene").getAsString() + " | " + row.get("channel").getAsString() + " | "
                        + row.get("figure").getAsString(), row);
                }
            }
        }
        return out;
    }

    private static void compare(StringBuilder md, Map<String, JsonObject> floatRows, Map<String, JsonObject> doubleRows) {
        md.append("## Against the truth (compare)\n\n")
            .append("Each row with a reference in both runs: the error of each against it (px, px/s, rad, ...).\n\n")
            .append("| scene | channel | figure | float | double | pymunk | closest |\n|---|---|---|---|---|---|---|\n");
        int doubleClosest = 0;
        int pymunkClosest = 0;
        int rows = 0;
        for (Map.Entry<String, JsonObject> e : doubleRows.entrySet()) {
            JsonObject f = floatRows.get(e.getKey());
            if (f == null) {
                continue;
            }
            double ef = number(f, "engineError");
            double ed = number(e.getValue(), "engineError");
            double ep = number(e.getValue(), "oracleError");
            String closest = closest(ef, ed, ep);
            doubleClosest += closest.equals("double") ? 1 : 0;
            pymunkClosest += closest.equals("pymunk") ? 1 : 0;
            rows++;
            md.append("| ").append(e.getKey()).append(" | ").append(g(ef)).append(" | ").append(g(ed)).append(" | ")
                .append(g(ep)).append(" | ").append(closest).append(" |\n");
        }
        md.append("\n").append(rows).append(" rows; closest: the double flavour alone in ").append(doubleClosest)
            .append(", pymunk alone in ").append(pymunkClosest).append(".\n\n");
    }

    private static void sweep(StringBuilder md, List<SweepPoint> points) {
        Map<String, SweepPoint> byKey = new HashMap<>();
        for (SweepPoint p : points) {
            byKey.put(SweepPoint.key(p.scene(), p.engine(), p.rate(), p.iterations()), p);
        }
        md.append("## Error against cost (sweep)\n\n")
            .append("Each point both flavours ran: whole-run error (maxError, px) and CPU time of the ticking thread (ms);")
            .append(" pymunk's error where it ran the point.\n\n")
            .append("| scene | ticks/s | iterations | float error | double error | pymunk error | float ms | double ms |")
            .append(" double / float cost |\n|---|---|---|---|---|---|---|---|---|\n");
        List<Double> ratios = new ArrayList<>();
        for (SweepPoint d : points) {
            if (!d.engine().equals("emini-double")) {
                continue;
            }
            SweepPoint f = byKey.get(SweepPoint.key(d.scene(), "emini", d.rate(), d.iterations()));
            if (f == null) {
                continue;
            }
            SweepPoint p = byKey.get(SweepPoint.key(d.scene(), "pymunk", d.rate(), d.iterations()));
            double ratio = d.cpuCostSeconds() / f.cpuCostSeconds();
            if (Double.isFinite(ratio)) {
                ratios.add(ratio);
            }
            md.append(String.format(Locale.ROOT, "| %s | %d | %d | %s | %s | %s | %s | %s | %s |%n", d.scene(), d.rate(),
                d.iterations(), g(f.maxError()), g(d.maxError()), p == null ? "" : g(p.maxError()),
                g(f.cpuCostSeconds() * 1e3), g(d.cpuCostSeconds() * 1e3), g(ratio)));
        }
        ratios.sort(null);
        if (!ratios.isEmpty()) {
            md.append(String.format(Locale.ROOT, "%nCost ratio double / float over %d points: median %s, range %s to %s"
                    + " (unpaired points: a noisy machine moves single points; see the median).%n", ratios.size(),
                g(ratios.get(ratios.size() / 2)), g(ratios.get(0)), g(ratios.get(ratios.size() - 1))));
        }
    }

    private static String closest(double f, double d, double p) {
        double best = Math.min(Math.min(nanMax(f), nanMax(d)), nanMax(p));
        if (Double.isInfinite(best)) {
            return "";
        }
        int at = (best == nanMax(f) ? 1 : 0) + (best == nanMax(d) ? 1 : 0) + (best == nanMax(p) ? 1 : 0);
        return at > 1 ? "tie" : best == nanMax(d) ? "double" : best == nanMax(f) ? "float" : "pymunk";
    }

    private static double nanMax(double v) {
        return Double.isNaN(v) ? Double.POSITIVE_INFINITY : Math.abs(v);
    }

    private static Double number(JsonObject o, String key) {
        JsonElement e = o.get(key);
        return e == null || e.isJsonNull() ? Double.NaN : e.getAsDouble();
    }

    private static String g(double v) {
        return Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.3g", v);
    }
}
