package org.emini.harness.oracle;

import com.google.gson.stream.JsonWriter;
import java.io.IOException;
import java.io.Writer;
import java.math.BigDecimal;
import java.math.MathContext;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * Writes the comparison: {@code compare.json} (every scene, every row) and {@code summary.md} (the
 * readable tables: first where the engine or pymunk is closer to the truth, then one table per scene).
 * Formats in harness/README.md (compare).
 */
public final class CompareReport {
    private CompareReport() {
    }

    /**
     * The counts over all scenes.
     *
     * @param scenes scenes compared
     * @param byStatus scenes per status
     * @param agree rows that agree
     * @param differ rows that differ
     * @param engineCloser rows where the engine is closer to the truth
     * @param oracleCloser rows where pymunk is closer
     * @param ties rows where both are as close
     * @param seconds wall time
     */
    public record Summary(int scenes, Map<CompareStatus, Integer> byStatus, int agree, int differ, int engineCloser,
                          int oracleCloser, int ties, double seconds) {

        /** Counts the rows of the scenes. */
        public static Summary of(List<Comparison.Scene> scenes, double seconds) {
            // In order of first appearance, as the summary line and compare.json print them.
            Map<CompareStatus, Integer> status = new LinkedHashMap<>();
            int agree = 0, differ = 0, engine = 0, oracle = 0, ties = 0;
            for (Comparison.Scene s : scenes) {
                status.merge(s.status(), 1, Integer::sum);
                for (Comparison.Row r : s.rows()) {
                    agree += r.agreement() == Agreement.AGREE ? 1 : 0;
                    differ += r.agreement() == Agreement.DIFFER ? 1 : 0;
                    engine += r.closer() == Closer.ENGINE ? 1 : 0;
                    oracle += r.closer() == Closer.ORACLE ? 1 : 0;
                    ties += r.closer() == Closer.TIE ? 1 : 0;
                }
            }
            return new Summary(scenes.size(), status, agree, differ, engine, oracle, ties, seconds);
        }

        /** Whether a scene could not be compared because of an error (an oracle bug, misaligned traces). */
        public boolean failed() {
            return byStatus.getOrDefault(CompareStatus.ERROR, 0) > 0;
        }

        @Override
        public String toString() {
            StringBuilder b = new StringBuilder();
            b.append(scenes).append(" scenes:");
            String sep = " ";
            for (Map.Entry<CompareStatus, Integer> e : byStatus.entrySet()) {
                b.append(sep).append(e.getValue()).append(' ').append(e.getKey().label());
                sep = ", ";
            }
            b.append(String.format(Locale.ROOT, "; rows: %d agree, %d differ; closer to the truth: engine %d, pymunk %d,"
                    + " tie %d (%.1f s)", agree, differ, engineCloser, oracleCloser, ties, seconds));
            return b.toString();
        }
    }

    /** Writes compare.json and summary.md into a folder. */
    public static void write(Path dir, List<Comparison.Scene> scenes, Summary summary, String command,
                             String pymunk) throws IOException {
        Files.createDirectories(dir);
        writeJson(dir.resolve("compare.json"), scenes, summary, command, pymunk);
        Files.writeString(dir.resolve("summary.md"), markdown(scenes, summary, command, pymunk), StandardCharsets.UTF_8);
    }

    private static void writeJson(Path file, List<Comparison.Scene> scenes, Summary summary, String command,
                                  String pymunk) throws IOException {
        try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            JsonWriter json = new JsonWriter(out);
            json.setIndent(" ");
            json.beginObject();
            json.name("format").value("emini-compare");
            json.name("version").value(1);
            json.name("generated").value(Instant.now().toString());
            json.name("command").value(command);
            json.name("oracle").value(pymunk);
            json.name("summary").beginObject();
            json.name("scenes").value(summary.scenes());
            json.name("status").beginObject();
            for (Map.Entry<CompareStatus, Integer> e : summary.byStatus().entrySet()) {
                json.name(e.getKey().label()).value(e.getValue());
            }
            json.endObject();
            json.name("agree").value(summary.agree());
            json.name("differ").value(summary.differ());
            json.name("closer").beginObject();
            json.name("engine").value(summary.engineCloser());
            json.name("oracle").value(summary.oracleCloser());
            json.name("tie").value(summary.ties());
            json.endObject();
            json.name("seconds").value(summary.seconds());
            json.endObject();
            json.name("scenes").beginArray();
            for (Comparison.Scene s : scenes) {
                json.beginObject();
                json.name("scene").value(s.scene());
                json.name("file").value(s.file());
                json.name("category").value(s.category());
                json.name("status").value(s.status().label());
                json.name("note").value(s.note());
                json.name("engine").value(s.engineStatus());
                json.name("oracle").beginObject();
                if (s.oracle() != null) {
                    json.name("status").value(s.oracle().status());
                    json.name("message").value(s.oracle().message());
                    notes(json, "unsupported", s.oracle().unsupported());
                    notes(json, "approximations", s.oracle().approximations());
                }
                json.endObject();
                json.name("chaotic").value(s.settings().chaotic());
                json.name("continuousCollision").value(s.settings().continuousCollision());
                json.name("closedForm").value(s.closedForm());
                json.name("rows").beginArray();
                for (Comparison.Row r : s.rows()) {
                    json.beginObject();
                    json.name("channel").value(r.channel());
                    json.name("figure").value(r.figure());
                    number(json.name("engine"), r.engine());
                    number(json.name("oracle"), r.oracle());
                    number(json.name("reference"), r.reference());
                    json.name("referenceSource").value(r.referenceSource());
                    number(json.name("difference"), r.difference());
                    number(json.name("tolerance"), r.tolerance());
                    number(json.name("engineError"), r.engineError());
                    number(json.name("oracleError"), r.oracleError());
                    json.name("agreement").value(r.agreement().label());
                    json.name("closer").value(r.closer().label());
                    json.endObject();
                }
                json.endArray();
                json.endObject();
            }
            json.endArray();
            json.endObject();
        }
    }

    private static void notes(JsonWriter json, String name, List<OracleScene.Note> notes) throws IOException {
        json.name(name).beginArray();
        for (OracleScene.Note n : notes) {
            json.beginObject();
            json.name("element").value(n.element());
            json.name("path").value(n.path());
            json.name("reason").value(n.reason());
            json.name("affectsBodies").value(n.affectsBodies());
            json.endObject();
        }
        json.endArray();
    }

    private static void number(JsonWriter json, double v) throws IOException {
        if (Double.isFinite(v)) {
            json.value(v);
        } else {
            json.nullValue();
        }
    }

    /** The readable summary. */
    static String markdown(List<Comparison.Scene> scenes, Summary summary, String command, String pymunk) {
        StringBuilder md = new StringBuilder();
        md.append("# Engine against pymunk\n\n");
        md.append("Made by `").append(command).append("` with ").append(pymunk).append(". ")
                .append("How rows, tolerances and verdicts are defined: scenarios/README.md, Comparison with the oracle.\n\n");
        md.append(summary).append("\n\n");
        md.append("## Closer to the truth\n\n");
        md.append("Every row with a reference (a closed form, or a law that holds for the scene). Errors are "
                + "|figure − reference|; for a series, reduced as its figure says (largest, final or rms error).\n\n");
        // Tally by reference first: which kind of truth each engine gets closer to.
        Map<String, int[]> tally = new TreeMap<>();
        for (Comparison.Scene s : scenes) {
            for (Comparison.Row r : s.rows()) {
                if (r.referenceSource() != null && r.closer() != Closer.NONE) {
                    int[] t = tally.computeIfAbsent(r.referenceSource(), k -> new int[3]);
                    t[r.closer() == Closer.ENGINE ? 0 : r.closer() == Closer.ORACLE ? 1 : 2]++;
                }
            }
        }
        md.append("| reference | engine closer | pymunk closer | tie |\n|---|---:|---:|---:|\n");
        for (Map.Entry<String, int[]> e : tally.entrySet()) {
            md.append("| ").append(e.getKey()).append(" | ").append(e.getValue()[0]).append(" | ")
                    .append(e.getValue()[1]).append(" | ").append(e.getValue()[2]).append(" |\n");
        }
        md.append("\n");
        md.append("| scene | metric | figure | reference | engine error | pymunk error | closer |\n");
        md.append("|---|---|---|---|---:|---:|---|\n");
        List<String[]> closer = new ArrayList<>();
        for (Comparison.Scene s : scenes) {
            for (Comparison.Row r : s.rows()) {
                if (r.referenceSource() == null) {
                    continue;
                }
                closer.add(new String[] {s.scene(), r.channel(), r.figure(), r.referenceSource(), fmt(r.engineError()),
                        fmt(r.oracleError()), shown(r.closer())});
            }
        }
        for (String[] c : closer) {
            md.append("| ").append(String.join(" | ", c)).append(" |\n");
        }
        md.append("\n## Scenes\n");
        for (Comparison.Scene s : scenes) {
            md.append("\n### ").append(s.scene()).append("\n\n");
            md.append("Status: **").append(s.status().label()).append("** (engine: ").append(s.engineStatus()).append(", pymunk: ")
                    .append(s.oracle() == null ? "not run" : s.oracle().status()).append(")");
            if (s.settings().chaotic()) {
                md.append("; chaotic: aggregates only");
            }
            md.append(".");
            if (!s.note().isEmpty()) {
                md.append(" ").append(s.note()).append(".");
            }
            md.append("\n\n");
            if (s.rows().isEmpty()) {
                continue;
            }
            md.append("| metric | figure | engine | pymunk | reference | difference | tolerance | agreement | closer |\n");
            md.append("|---|---|---:|---:|---|---:|---:|---|---|\n");
            for (Comparison.Row r : s.rows()) {
                String ref = r.referenceSource() == null ? "" : fmt(r.reference()) + " (" + r.referenceSource() + ")";
                md.append("| ").append(r.channel()).append(" | ").append(r.figure()).append(" | ").append(fmt(r.engine()))
                        .append(" | ").append(fmt(r.oracle())).append(" | ").append(ref).append(" | ")
                        .append(fmt(r.difference())).append(" | ").append(fmt(r.tolerance())).append(" | ")
                        .append(r.agreement().label()).append(" | ").append(shown(r.closer()))
                        .append(" |\n");
            }
        }
        return md.toString();
    }

    /** The closer side as summary.md names it: the oracle by its name. */
    private static String shown(Closer c) {
        return c == Closer.ORACLE ? "pymunk" : c.label();
    }

    /** Four significant digits, no exponent for ordinary magnitudes; "-" for a missing figure. */
    static String fmt(double v) {
        if (Double.isNaN(v)) {
            return "-";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        if (v == 0) {
            return "0";
        }
        double a = Math.abs(v);
        if (a >= 1e-3 && a < 1e7) {
            return new BigDecimal(v).round(new MathContext(4)).stripTrailingZeros().toPlainString();
        }
        return String.format(Locale.ROOT, "%.3e", v);
    }
}
