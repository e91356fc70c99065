package org.emini.harness.report;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * Two runs' results side by side ({@code harness diff OLD NEW}): each scene's verdict
 * ({@code results.json}), each comparison row's error against the truth ({@code compare/compare.json}),
 * each benchmark scene's CPU time per tick ({@code bench/bench.json}) and, for scenes that ran long enough
 * to time, the run's wall time per tick ({@code results.json}). A change for the worse beyond its
 * tolerance is a regression (harness/README.md, diff). {@link #sameState} compares the scenes' state
 * hashes alone: two runs that must be bit for bit the same (one thread against two, a build before an
 * optimisation against one after).
 */
public final class RunDiff {
    /**
     * The tolerances.
     *
     * @param accuracy relative growth of an error against the truth that is still no regression (0.1: 10%)
     * @param speed relative growth of a benchmark's CPU time per tick that is still no regression
     * @param runSpeed relative growth of a run's wall time per tick that is still no regression
     * @param runMillis scenes whose run took less than this (ms, in either run) are not timed
     */
    public record Tolerances(double accuracy, double speed, double runSpeed, double runMillis) {
    }

    /**
     * One figure that changed.
     *
     * @param kind {@code verdict}, {@code accuracy}, {@code speed} (benchmark), {@code run speed} or
     *     {@code state} (a scene's state hash, {@link #sameState})
     * @param scene the scene
     * @param what the row, channel or engine
     * @param before the old figure (a verdict or a number)
     * @param after the new figure
     * @param regression whether it is worse beyond the tolerance (else better beyond it)
     */
    public record Change(String kind, String scene, String what, String before, String after, boolean regression) {
    }

    /**
     * The outcome.
     *
     * @param changes the regressions and the improvements
     * @param compared how many figures were compared, by kind ({@code state hashes} for {@link #sameState})
     * @param notes what could not be compared (a file only one side has, scenes only one side ran, scenes
     *     without a state hash), and how many scenes have the same state
     */
    public record Result(List<Change> changes, Map<String, Integer> compared, List<String> notes) {
        /** The regressions. */
        public List<Change> regressions() {
            return changes.stream().filter(Change::regression).toList();
        }
    }

    private RunDiff() {
    }

    /** The results found at a path: a reports folder (results.json, compare/, bench/) or one of those files. */
    static Map<String, JsonObject> documents(Path p) throws IOException {
        Map<String, JsonObject> out = new LinkedHashMap<>();
        if (Files.isDirectory(p)) {
            for (String f : List.of("results.json", "compare/compare.json", "compare.json", "bench/bench.json", "bench.json")) {
                Path file = p.resolve(f);
                if (Files.isRegularFile(file)) {
                    JsonObject doc = read(file);
                    out.putIfAbsent(format(doc, file), doc);
                }
            }
        } else if (Files.isRegularFile(p)) {
            JsonObject doc = read(p);
            out.put(format(doc, p), doc);
        } else {
            throw new IOException(p + ": no such file or folder");
        }
        if (out.isEmpty()) {
            throw new IOException(p + ": holds no results.json, compare/compare.json or bench/bench.json");
        }
        return out;
    }

    private static JsonObject read(Path file) throws IOException {
        try {
            return JsonParser.parseString(Files.readString(file, StandardCharsets.UTF_8)).getAsJsonObject();
        } catch (JsonParseException | IllegalStateException e) {
            throw new IOException(file + ": not valid JSON: " + e.getMessage(), e);
        }
    }

    private static String format(JsonObject doc, Path file) throws IOException {
        String f = doc.has("format") ? doc.get("format").getAsString() : "";
        if (!Set.of("emini-results", "emini-compare", "emini-bench").contains(f)) {
            throw new IOException(file + ": not a harness results, comparison or benchmark file (format '" + f + "')");
        }
        return f;
    }

    /** Compares two runs. */
    public static Result diff(Path before, Path after, Tolerances tol) throws IOException {
        Map<String, JsonObject> a = documents(before);
        Map<String, JsonObject> b = documents(after);
        List<Change> changes = new ArrayList<>();
        Map<String, Integer> compared = new LinkedHashMap<>();
        List<String> notes = new ArrayList<>();
        for (String f : List.of("emini-results", "emini-compare", "emini-bench")) {
            if (a.containsKey(f) != b.containsKey(f)) {
                notes.add(f + " only in " + (a.containsKey(f) ? "OLD" : "NEW") + ": not compared");
            }
        }
        if (a.containsKey("emini-results") && b.containsKey("emini-results")) {
            results(a.get("emini-results"), b.get("emini-results"), tol, changes, compared, notes);
        }
        if (a.containsKey("emini-compare") && b.containsKey("emini-compare")) {
            accuracy(a.get("emini-compare"), b.get("emini-compare"), tol, changes, compared);
        }
        if (a.containsKey("emini-bench") && b.containsKey("emini-bench")) {
            bench(a.get("emini-bench"), b.get("emini-bench"), tol, changes, compared);
        }
        return new Result(changes, compared, notes);
    }

    /**
     * Compares only the scenes' state hashes ({@code diff --same-state}): every scene that both runs ran
     * to its end must have the same one, else it is a regression of kind {@code state}. Scenes only one
     * side ran, and those without a hash (unsupported, or stopped by an error: {@code SceneResult.stateHash}),
     * are notes.
     */
    public static Result sameState(Path before, Path after) throws IOException {
        JsonObject a = documents(before).get("emini-results");
        JsonObject b = documents(after).get("emini-results");
        List<Change> changes = new ArrayList<>();
        Map<String, Integer> compared = new LinkedHashMap<>();
        List<String> notes = new ArrayList<>();
        if (a == null || b == null) {
            notes.add((a == null && b == null ? "results.json in neither OLD nor NEW"
                    : "results.json only in " + (a != null ? "OLD" : "NEW")) + ": no states to compare");
            return new Result(changes, compared, notes);
        }
        States st = states(a, b);
        for (String[] d : st.differing()) {
            changes.add(new Change("state", d[0], "stateHash", d[1], d[2], true));
        }
        if (st.compared() > 0) {
            compared.put("state hashes", st.compared());
        }
        notes.add(st.sameNote());
        names(notes, st.onlyOld(), "of OLD not in NEW");
        names(notes, st.onlyNew(), "of NEW not in OLD");
        names(notes, st.unhashed(), "without a state hash in OLD or NEW (unsupported, or stopped by an error)");
        return new Result(changes, compared, notes);
    }

    /**
     * The scenes' state hashes side by side.
     *
     * @param compared scenes in both with a hash in both
     * @param same those of them whose hashes are equal
     * @param differing the others: scene, OLD's hash, NEW's hash
     * @param onlyOld scenes only OLD ran
     * @param onlyNew scenes only NEW ran
     * @param unhashed scenes in both without a hash on one side or both
     */
    private record States(int compared, int same, List<String[]> differing, List<String> onlyOld, List<String> onlyNew,
                          List<String> unhashed) {
        String sameNote() {
            return same + " of " + compared + " scenes with a state hash in both have the same state";
        }
    }

    private static States states(JsonObject a, JsonObject b) {
        Map<String, JsonObject> old = byKey(a, "scenes", s -> s.get("scene").getAsString());
        Map<String, JsonObject> now = byKey(b, "scenes", s -> s.get("scene").getAsString());
        int same = 0;
        List<String[]> differing = new ArrayList<>();
        List<String> onlyOld = new ArrayList<>();
        List<String> unhashed = new ArrayList<>();
        for (Map.Entry<String, JsonObject> e : old.entrySet()) {
            JsonObject s = now.get(e.getKey());
            if (s == null) {
                onlyOld.add(e.getKey());
            } else if (!has(e.getValue(), "stateHash") || !has(s, "stateHash")) {
                unhashed.add(e.getKey());
            } else if (e.getValue().get("stateHash").getAsString().equals(s.get("stateHash").getAsString())) {
                same++;
            } else {
                differing.add(new String[] {e.getKey(), e.getValue().get("stateHash").getAsString(),
                    s.get("stateHash").getAsString()});
            }
        }
        List<String> onlyNew = new ArrayList<>(now.keySet());
        onlyNew.removeAll(old.keySet());
        return new States(same + differing.size(), same, differing, onlyOld, onlyNew, unhashed);
    }

    /** A note naming scenes ("3 scenes WHAT: a, b, c"), the first ten; none when there are none. */
    private static void names(List<String> notes, List<String> scenes, String what) {
        if (!scenes.isEmpty()) {
            notes.add(scenes.size() + " scenes " + what + ": " + String.join(", ", scenes.subList(0, Math.min(10, scenes.size())))
                    + (scenes.size() > 10 ? ", ..." : ""));
        }
    }

    private static void results(JsonObject a, JsonObject b, Tolerances tol, List<Change> out, Map<String, Integer> n,
                                List<String> notes) {
        Map<String, JsonObject> old = byKey(a, "scenes", s -> s.get("scene").getAsString());
        Map<String, JsonObject> now = byKey(b, "scenes", s -> s.get("scene").getAsString());
        for (Map.Entry<String, JsonObject> e : old.entrySet()) {
            JsonObject s = now.get(e.getKey());
            if (s == null) {
                continue;
            }
            n.merge("verdict", 1, Integer::sum);
            String was = e.getValue().get("status").getAsString();
            String is = s.get("status").getAsString();
            boolean wasBad = was.equals("FAIL") || was.equals("ERROR");
            boolean isBad = is.equals("FAIL") || is.equals("ERROR");
            if (isBad != wasBad) {
                out.add(new Change("verdict", e.getKey(), "status", was, is, isBad));
            }
            double runA = number(e.getValue(), "runMillis");
            double runB = number(s, "runMillis");
            if (runA >= tol.runMillis() && runB >= tol.runMillis()) {
                n.merge("run speed", 1, Integer::sum);
                ratio("run speed", e.getKey(), "wall µs/tick", number(e.getValue(), "microsPerTick"),
                        number(s, "microsPerTick"), tol.runSpeed(), 0, out);
            }
        }
        States st = states(a, b);
        if (!st.onlyOld().isEmpty()) {
            notes.add(st.onlyOld().size() + " scenes of OLD not in NEW: not compared");
        }
        if (st.compared() > 0) {
            notes.add(st.sameNote() + " (bit for bit; diff --same-state fails on the others)");
        }
    }

    private static void accuracy(JsonObject a, JsonObject b, Tolerances tol, List<Change> out, Map<String, Integer> n) {
        Map<String, JsonObject> now = rows(b);
        for (Map.Entry<String, JsonObject> e : rows(a).entrySet()) {
            JsonObject r = now.get(e.getKey());
            JsonObject was = e.getValue();
            if (r == null || !has(was, "referenceSource")) {
                continue;
            }
            double before = number(was, "engineError");
            double after = number(r, "engineError");
            if (Double.isNaN(before)) {
                continue;
            }
            n.merge("accuracy", 1, Integer::sum);
            String scene = e.getKey().substring(0, e.getKey().indexOf('|'));
            String what = was.get("channel").getAsString() + " " + was.get("figure").getAsString() + " against "
                    + was.get("referenceSource").getAsString();
            // Float noise: a hundredth of the row's agreement tolerance, and at least 1e-9.
            double floor = Math.max(1e-9, 0.01 * Math.max(0, number(was, "tolerance")));
            ratio("accuracy", scene, what, before, after, tol.accuracy(), floor, out);
        }
    }

    private static Map<String, JsonObject> rows(JsonObject doc) {
        Map<String, JsonObject> out = new LinkedHashMap<>();
        for (JsonElement s : array(doc, "scenes")) {
            JsonObject scene = s.getAsJsonObject();
            for (JsonElement r : array(scene, "rows")) {
                JsonObject row = r.getAsJsonObject();
                out.put(scene.get("scene").getAsString() + "|" + row.get("channel").getAsString() + "|"
                        + row.get("figure").getAsString(), row);
            }
        }
        return out;
    }

    private static void bench(JsonObject a, JsonObject b, Tolerances tol, List<Change> out, Map<String, Integer> n) {
        Map<String, JsonObject> now = byKey(b, "scenes", s -> s.get("id").getAsString());
        for (Map.Entry<String, JsonObject> e : byKey(a, "scenes", s -> s.get("id").getAsString()).entrySet()) {
            JsonObject s = now.get(e.getKey());
            if (s == null) {
                continue;
            }
            Map<String, JsonObject> cells = byKey(s, "results", m -> m.get("engine").getAsString());
            for (Map.Entry<String, JsonObject> c : byKey(e.getValue(), "results", m -> m.get("engine").getAsString()).entrySet()) {
                JsonObject m = cells.get(c.getKey());
                double before = number(c.getValue(), "cpuMsPerTick");
                double after = m == null ? Double.NaN : number(m, "cpuMsPerTick");
                if (Double.isNaN(before) || Double.isNaN(after)) {
                    continue;
                }
                n.merge("speed", 1, Integer::sum);
                ratio("speed", e.getKey(), c.getKey() + " CPU ms/tick", before, after, tol.speed(), 0, out);
            }
        }
    }

    /** Adds a change when {@code after} is beyond {@code before} × (1 ± tol) ± floor; a lost figure is worse. */
    private static void ratio(String kind, String scene, String what, double before, double after, double tol, double floor,
                              List<Change> out) {
        if (Double.isNaN(before)) {
            return;
        }
        boolean worse = Double.isNaN(after) || after > before * (1 + tol) + floor;
        boolean better = !worse && after < before / (1 + tol) - floor;
        if (worse || better) {
            out.add(new Change(kind, scene, what, fmt(before), fmt(after), worse));
        }
    }

    private interface Key {
        String of(JsonObject o);
    }

    private static Map<String, JsonObject> byKey(JsonObject doc, String array, Key key) {
        Map<String, JsonObject> out = new LinkedHashMap<>();
        for (JsonElement e : array(doc, array)) {
            out.put(key.of(e.getAsJsonObject()), e.getAsJsonObject());
        }
        return out;
    }

    private static Iterable<JsonElement> array(JsonObject o, String key) {
        return o.has(key) && o.get(key).isJsonArray() ? o.getAsJsonArray(key) : List.of();
    }

    private static boolean has(JsonObject o, String key) {
        return o.has(key) && !o.get(key).isJsonNull();
    }

    /** A number field, NaN when absent or null (a figure that was not finite). */
    private static double number(JsonObject o, String key) {
        return has(o, key) && o.get(key).isJsonPrimitive() && o.get(key).getAsJsonPrimitive().isNumber()
                ? o.get(key).getAsDouble() : Double.NaN;
    }

    private static String fmt(double v) {
        return Double.isNaN(v) ? "-" : String.format(Locale.ROOT, "%.4g", v);
    }
}
