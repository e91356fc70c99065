package org.emini.harness.oracle;

import com.google.gson.stream.JsonWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.emini.harness.metrics.PenetrationPair;

/**
 * The engine against several oracles at once (pymunk and Box2D v3): each oracle's {@link Comparison} of a
 * scene merged row by row, and "closer to the truth" ranking the engine and every oracle that ran
 * (scenarios/README.md, Comparison with the oracle). Writes compare.json version 2 and summary.md.
 */
public final class MultiComparison {
    /** The name the engine has in rankings and reports. */
    public static final String ENGINE = "emini";

    private MultiComparison() {
    }

    /**
     * One oracle's side of a row.
     *
     * @param value the oracle's figure
     * @param error |figure − reference| reduced as the row's figure says, NaN without reference
     * @param difference engine − oracle (series: the largest |engine − oracle|)
     * @param tolerance the largest difference that agrees
     * @param agreement whether the engine and this oracle agree
     */
    public record Cell(double value, double error, double difference, double tolerance, Agreement agreement) {
    }

    /**
     * A merged row.
     *
     * @param channel the channel
     * @param figure how its samples reduce
     * @param engine the engine's figure
     * @param reference the truth's figure, NaN without one
     * @param referenceSource where the truth comes from, or null
     * @param engineError the engine's error against the truth
     * @param oracles each oracle's side, by name
     * @param closer the engine or oracle closest to the truth, {@code tie} when the two closest are within float
     *     noise or 5% of each other, {@code -} when fewer than two could be judged
     * @param ranking the judged sides, closest first
     */
    public record Row(String channel, String figure, double engine, double reference, String referenceSource,
                      double engineError, Map<String, Cell> oracles, String closer, List<String> ranking) {
    }

    /**
     * A scene against every oracle.
     *
     * @param first the first oracle's comparison (scene, file, settings, engine status)
     * @param byOracle each oracle's comparison, by name
     * @param status compared when any oracle compared; error when any could not
     * @param rows the merged table
     */
    public record Scene(Comparison.Scene first, Map<String, Comparison.Scene> byOracle, CompareStatus status,
                        List<Row> rows) {
    }

    /**
     * A pair of bodies among the deepest overlapping ones of any engine, with each engine's figure.
     *
     * @param a the first body's scene name
     * @param b the second's, or {@code landscape}
     * @param max each engine's deepest overlap of the pair over the run (px; 0 when it never overlapped), by
     *     engine name ({@code emini} first), for the engines that ran
     */
    public record PairRow(String a, String b, Map<String, Double> max) {
    }

    /** How many of each engine's deepest pairs {@link #pairs} puts side by side. */
    static final int TOP_PAIRS = 3;

    /**
     * The deepest overlapping pairs of each engine (its {@value #TOP_PAIRS} deepest), each with every engine's
     * figure for the same pair, deepest first; empty when no engine computed penetration.
     */
    public static List<PairRow> pairs(Scene s) {
        Map<String, List<PenetrationPair>> by = new LinkedHashMap<>();
        Comparison.Scene first = s.first();
        if (first.enginePairs() != null) {
            by.put(ENGINE, first.enginePairs());
        }
        s.byOracle().forEach((o, c) -> {
            if (c.oraclePairs() != null) {
                by.put(o, c.oraclePairs());
            }
        });
        Map<List<String>, PairRow> rows = new LinkedHashMap<>();
        by.values().forEach(list -> list.stream().limit(TOP_PAIRS).forEach(p ->
                rows.computeIfAbsent(List.of(p.a(), p.b()), k -> new PairRow(p.a(), p.b(), new LinkedHashMap<>()))));
        for (PairRow r : rows.values()) {
            by.forEach((engine, list) -> r.max().put(engine, list.stream()
                    .filter(p -> p.a().equals(r.a()) && p.b().equals(r.b())).mapToDouble(PenetrationPair::max)
                    .findFirst().orElse(0)));
        }
        List<PairRow> out = new ArrayList<>(rows.values());
        out.sort(Comparator.comparingDouble((PairRow r) -> -r.max().values().stream()
                .mapToDouble(Double::doubleValue).max().orElse(0)));
        return out;
    }

    /** Merges one scene's comparisons, one per oracle (in the order given). */
    public static Scene merge(Map<String, Comparison.Scene> byOracle) {
        Map<String, List<Comparison.Row>> byKey = new LinkedHashMap<>();
        Map<String, Map<String, Comparison.Row>> sides = new LinkedHashMap<>();
        CompareStatus status = null;
        for (Map.Entry<String, Comparison.Scene> e : byOracle.entrySet()) {
            CompareStatus st = e.getValue().status();
            if (st == CompareStatus.ERROR || status == null || (status != CompareStatus.ERROR && st == CompareStatus.COMPARED)) {
                status = st;
            }
            for (Comparison.Row r : e.getValue().rows()) {
                String key = r.channel() + "|" + r.figure();
                byKey.computeIfAbsent(key, k -> new ArrayList<>()).add(r);
                sides.computeIfAbsent(key, k -> new LinkedHashMap<>()).put(e.getKey(), r);
            }
        }
        List<Row> rows = new ArrayList<>();
        for (Map.Entry<String, List<Comparison.Row>> e : byKey.entrySet()) {
            Comparison.Row any = e.getValue().get(0);
            Map<String, Cell> cells = new LinkedHashMap<>();
            Map<String, Double> errors = new LinkedHashMap<>();
            double engine = any.engine();
            double engineError = any.engineError();
            boolean judged = false;
            double scale = Math.abs(Double.isFinite(any.reference()) ? any.reference() : 0);
            for (Map.Entry<String, Comparison.Row> s : sides.get(e.getKey()).entrySet()) {
                Comparison.Row r = s.getValue();
                if (Double.isNaN(engine)) {
                    engine = r.engine();
                    engineError = r.engineError();
                }
                cells.put(s.getKey(), new Cell(r.oracle(), r.oracleError(), r.difference(), r.tolerance(), r.agreement()));
                if (r.closer() != Closer.NONE) {
                    judged = true;
                    errors.put(s.getKey(), r.oracleError());
                }
                for (double v : new double[] {r.engine(), r.oracle()}) {
                    if (Double.isFinite(v)) {
                        scale = Math.max(scale, Math.abs(v));
                    }
                }
            }
            String closer = "-";
            List<String> ranking = List.of();
            if (judged && any.referenceSource() != null) {
                Map<String, Double> all = new LinkedHashMap<>();
                all.put(ENGINE, engineError);
                all.putAll(errors);
                ranking = rank(all);
                Closer top = Comparison.closer(orInf(all.get(ranking.get(0))), orInf(all.get(ranking.get(1))), scale);
                closer = top == Closer.TIE ? "tie" : ranking.get(0);
            }
            rows.add(new Row(any.channel(), any.figure(), engine, any.reference(), any.referenceSource(), engineError,
                    cells, closer, ranking));
        }
        Comparison.Scene first = byOracle.values().iterator().next();
        return new Scene(first, byOracle, status, rows);
    }

    private static double orInf(Double d) {
        return d == null || Double.isNaN(d) ? Double.POSITIVE_INFINITY : d;
    }

    /** The sides by error, smallest first (NaN last); ties keep the given order (the engine first). */
    static List<String> rank(Map<String, Double> errors) {
        List<String> out = new ArrayList<>(errors.keySet());
        out.sort(Comparator.comparingDouble(k -> orInf(errors.get(k))));
        return out;
    }

    /**
     * Counts over all scenes.
     *
     * @param scenes scenes compared
     * @param status per oracle, scenes per status
     * @param agree per oracle, rows that agree with the engine
     * @param differ per oracle, rows that differ
     * @param closer rows closest to the truth per side (emini, each oracle, tie)
     * @param seconds wall time
     */
    public record Summary(int scenes, Map<String, Map<CompareStatus, Integer>> status, Map<String, Integer> agree,
                          Map<String, Integer> differ, Map<String, Integer> closer, double seconds) {

        /** Counts the scenes' rows. */
        public static Summary of(List<Scene> scenes, List<String> oracles, double seconds) {
            Map<String, Map<CompareStatus, Integer>> status = new LinkedHashMap<>();
            Map<String, Integer> agree = new LinkedHashMap<>();
            Map<String, Integer> differ = new LinkedHashMap<>();
            Map<String, Integer> closer = new LinkedHashMap<>();
            closer.put(ENGINE, 0);
            for (String o : oracles) {
                status.put(o, new LinkedHashMap<>());
                agree.put(o, 0);
                differ.put(o, 0);
                closer.put(o, 0);
            }
            closer.put("tie", 0);
            for (Scene s : scenes) {
                s.byOracle().forEach((o, c) -> status.get(o).merge(c.status(), 1, Integer::sum));
                for (Row r : s.rows()) {
                    r.oracles().forEach((o, c) -> {
                        agree.merge(o, c.agreement() == Agreement.AGREE ? 1 : 0, Integer::sum);
                        differ.merge(o, c.agreement() == Agreement.DIFFER ? 1 : 0, Integer::sum);
                    });
                    if (!r.closer().equals("-")) {
                        closer.merge(r.closer(), 1, Integer::sum);
                    }
                }
            }
            return new Summary(scenes.size(), status, agree, differ, closer, seconds);
        }

        /** Whether a scene could not be compared by some oracle because of an error. */
        public boolean failed() {
            return status.values().stream().anyMatch(m -> m.getOrDefault(CompareStatus.ERROR, 0) > 0);
        }

        @Override
        public String toString() {
            StringBuilder b = new StringBuilder().append(scenes).append(" scenes");
            status.forEach((o, m) -> {
                b.append("; ").append(o).append(':');
                String sep = " ";
                for (Map.Entry<CompareStatus, Integer> e : m.entrySet()) {
                    b.append(sep).append(e.getValue()).append(' ').append(e.getKey().label());
                    sep = ", ";
                }
                b.append(", rows ").append(agree.get(o)).append(" agree, ").append(differ.get(o)).append(" differ");
            });
            b.append("; closer to the truth:");
            closer.forEach((k, v) -> b.append(' ').append(k).append(' ').append(v));
            return b.append(String.format(java.util.Locale.ROOT, " (%.1f s)", seconds)).toString();
        }
    }

    /** Writes compare.json (version 2) and summary.md. */
    public static void write(Path dir, List<Scene> scenes, Summary summary, String command, List<String> oracles,
                             String versions) throws IOException {
        Files.createDirectories(dir);
        try (Writer out = Files.newBufferedWriter(dir.resolve("compare.json"), StandardCharsets.UTF_8)) {
            json(new JsonWriter(out), scenes, summary, command, oracles, versions);
        }
        Files.writeString(dir.resolve("summary.md"), markdown(scenes, summary, command, oracles, versions),
                StandardCharsets.UTF_8);
    }

    private static void json(JsonWriter json, List<Scene> scenes, Summary summary, String command, List<String> oracles,
                             String versions) throws IOException {
        json.setIndent(" ");
        json.beginObject();
        json.name("format").value("emini-compare");
        json.name("version").value(2);
        json.name("generated").value(Instant.now().toString());
        json.name("command").value(command);
        json.name("oracle").value(versions);
        json.name("oracles").beginArray();
        for (String o : oracles) {
            json.value(o);
        }
        json.endArray();
        json.name("summary").beginObject();
        json.name("scenes").value(summary.scenes());
        json.name("status").beginObject();
        for (Map.Entry<String, Map<CompareStatus, Integer>> e : summary.status().entrySet()) {
            json.name(e.getKey()).beginObject();
            for (Map.Entry<CompareStatus, Integer> s : e.getValue().entrySet()) {
                json.name(s.getKey().label()).value(s.getValue());
            }
            json.endObject();
        }
        json.endObject();
        counts(json, "agree", summary.agree());
        counts(json, "differ", summary.differ());
        counts(json, "closer", summary.closer());
        json.name("seconds").value(summary.seconds());
        json.endObject();
        json.name("scenes").beginArray();
        for (Scene s : scenes) {
            Comparison.Scene f = s.first();
            json.beginObject();
            json.name("scene").value(f.scene());
            json.name("file").value(f.file());
            json.name("category").value(f.category());
            json.name("status").value(s.status().label());
            json.name("engine").value(f.engineStatus());
            json.name("oracles").beginObject();
            for (Map.Entry<String, Comparison.Scene> e : s.byOracle().entrySet()) {
                Comparison.Scene c = e.getValue();
                json.name(e.getKey()).beginObject();
                json.name("status").value(c.status().label());
                json.name("note").value(c.note());
                if (c.oracle() != null) {
                    json.name("run").value(c.oracle().status());
                    json.name("message").value(c.oracle().message());
                }
                json.endObject();
            }
            json.endObject();
            json.name("chaotic").value(f.settings().chaotic());
            json.name("continuousCollision").value(f.settings().continuousCollision());
            json.name("closedForm").value(f.closedForm());
            List<PairRow> pairs = pairs(s);
            if (!pairs.isEmpty()) {
                json.name("penetrationPairs").beginArray();
                for (PairRow p : pairs) {
                    json.beginObject();
                    json.name("a").value(p.a());
                    json.name("b").value(p.b());
                    json.name("max").beginObject();
                    for (Map.Entry<String, Double> m : p.max().entrySet()) {
                        number(json.name(m.getKey()), m.getValue());
                    }
                    json.endObject();
                    json.endObject();
                }
                json.endArray();
            }
            json.name("rows").beginArray();
            for (Row r : s.rows()) {
                json.beginObject();
                json.name("channel").value(r.channel());
                json.name("figure").value(r.figure());
                number(json.name("engine"), r.engine());
                number(json.name("reference"), r.reference());
                json.name("referenceSource").value(r.referenceSource());
                number(json.name("engineError"), r.engineError());
                Cell firstCell = r.oracles().values().iterator().next();
                number(json.name("tolerance"), firstCell.tolerance());
                json.name("oracles").beginObject();
                for (Map.Entry<String, Cell> c : r.oracles().entrySet()) {
                    json.name(c.getKey()).beginObject();
                    number(json.name("value"), c.getValue().value());
                    number(json.name("error"), c.getValue().error());
                    number(json.name("difference"), c.getValue().difference());
                    number(json.name("tolerance"), c.getValue().tolerance());
                    json.name("agreement").value(c.getValue().agreement().label());
                    json.endObject();
                }
                json.endObject();
                json.name("closer").value(r.closer());
                json.name("ranking").beginArray();
                for (String k : r.ranking()) {
                    json.value(k);
                }
                json.endArray();
                json.endObject();
            }
            json.endArray();
            json.endObject();
        }
        json.endArray();
        json.endObject();
    }

    private static void counts(JsonWriter json, String name, Map<String, Integer> m) throws IOException {
        json.name(name).beginObject();
        for (Map.Entry<String, Integer> e : m.entrySet()) {
            json.name(e.getKey()).value(e.getValue());
        }
        json.endObject();
    }

    private static void number(JsonWriter json, double v) throws IOException {
        if (Double.isFinite(v)) {
            json.value(v);
        } else {
            json.nullValue();
        }
    }

    static String markdown(List<Scene> scenes, Summary summary, String command, List<String> oracles, String versions) {
        StringBuilder md = new StringBuilder("# Engine against " + String.join(" and ", oracles) + "\n\n");
        md.append("Made by `").append(command).append("` with ").append(versions)
                .append(". Rows, tolerances and verdicts: scenarios/README.md, Comparison with the oracle.\n\n");
        md.append(summary).append("\n\n## Closer to the truth\n\n");
        md.append("Rows with a reference (a closed form, or a law that holds for the scene), the engine and every "
                + "oracle that ran ranked by their error; a tie when the two closest are within float noise or 5%.\n\n");
        List<String> sides = new ArrayList<>(List.of(ENGINE));
        sides.addAll(oracles);
        sides.add("tie");
        Map<String, Map<String, Integer>> tally = new TreeMap<>();
        for (Scene s : scenes) {
            for (Row r : s.rows()) {
                if (r.referenceSource() != null && !r.closer().equals("-")) {
                    tally.computeIfAbsent(r.referenceSource(), k -> new LinkedHashMap<>()).merge(r.closer(), 1, Integer::sum);
                }
            }
        }
        md.append("| reference | ").append(String.join(" | ", sides)).append(" |\n|---|");
        md.append("---:|".repeat(sides.size())).append('\n');
        tally.forEach((ref, t) -> {
            md.append("| ").append(ref);
            sides.forEach(k -> md.append(" | ").append(t.getOrDefault(k, 0)));
            md.append(" |\n");
        });
        md.append("| all");
        sides.forEach(k -> md.append(" | ").append(summary.closer().getOrDefault(k, 0)));
        md.append(" |\n\n## Scenes\n");
        for (Scene s : scenes) {
            md.append("\n### ").append(s.first().scene()).append("\n\n");
            md.append("Status: **").append(s.status().label()).append("** (engine: ").append(s.first().engineStatus());
            s.byOracle().forEach((o, c) -> md.append("; ").append(o).append(": ").append(c.status().label())
                    .append(c.note().isEmpty() ? "" : " (" + c.note() + ")"));
            md.append(").\n\n");
            List<PairRow> pairs = pairs(s);
            if (!pairs.isEmpty()) {
                List<String> engines = new ArrayList<>(pairs.get(0).max().keySet());
                md.append("Deepest overlapping pairs (px, each engine's deepest overlap of the pair over the run):\n\n| pair");
                engines.forEach(k -> md.append(" | ").append(k));
                md.append(" |\n|---");
                engines.forEach(k -> md.append("|---:"));
                md.append("|\n");
                for (PairRow p : pairs) {
                    md.append("| ").append(p.a()).append(" – ").append(p.b());
                    engines.forEach(k -> md.append(" | ").append(CompareReport.fmt(p.max().get(k))));
                    md.append(" |\n");
                }
                md.append('\n');
            }
            if (s.rows().isEmpty()) {
                continue;
            }
            md.append("| metric | figure | emini");
            oracles.forEach(o -> md.append(" | ").append(o).append(" | difference | tolerance | agreement"));
            md.append(" | reference | ranking |\n|---|---|---:");
            oracles.forEach(o -> md.append("|---:|---:|---:|---"));
            md.append("|---|---|\n");
            for (Row r : s.rows()) {
                md.append("| ").append(r.channel()).append(" | ").append(r.figure()).append(" | ")
                        .append(CompareReport.fmt(r.engine()));
                for (String o : oracles) {
                    Cell c = r.oracles().get(o);
                    md.append(c == null ? " | - | - | - | -" : " | " + CompareReport.fmt(c.value()) + " | "
                            + CompareReport.fmt(c.difference()) + " | " + CompareReport.fmt(c.tolerance()) + " | "
                            + c.agreement().label());
                }
                md.append(" | ").append(r.referenceSource() == null ? "" : CompareReport.fmt(r.reference()) + " ("
                        + r.referenceSource() + ")").append(" | ").append(String.join(" < ", r.ranking())).append(" |\n");
            }
        }
        return md.toString();
    }
}
