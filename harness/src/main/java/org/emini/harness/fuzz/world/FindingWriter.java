package org.emini.harness.fuzz.world;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonObject;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Writes a finding so that it reproduces without Java: {@code NAME.json} always (the violation, the
 * generator's seed, world index and profile, the ids of the elements the shrinker kept, and the shrunk
 * recipe itself: a complete description of the world), and {@code NAME.yaml}, a scene in the
 * harness's scenario language with an expectation that fails the same way, when the scene language
 * can say everything the shrunk world holds. {@code ./emini fuzz --replay NAME.json} checks it again.
 */
public final class FindingWriter {
    private static final Gson GSON = new GsonBuilder().setPrettyPrinting().serializeSpecialFloatingPointValues().create();

    private FindingWriter() {
    }

    /** Writes the files into {@code dir}; returns the JSON file. */
    public static Path write(Path dir, Finding f) throws IOException {
        Files.createDirectories(dir);
        Recipe r = f.original();
        String name = f.violation().kind().name().toLowerCase().replace('_', '-') + "-" + r.seed + "-" + r.profile.name().toLowerCase()
                + "-" + r.index;
        Path json = dir.resolve(name + ".json");
        JsonObject o = new JsonObject();
        o.addProperty("kind", f.violation().kind().name());
        o.addProperty("violation", f.violation().toString());
        o.addProperty("shrunkViolation", f.shrunkViolation().toString());
        o.addProperty("tick", f.shrunkViolation().tick());
        o.addProperty("seed", r.seed);
        o.addProperty("index", r.index);
        o.addProperty("profile", r.profile.name());
        o.addProperty("original", r.summary());
        o.addProperty("shrunk", f.shrunk().summary());
        o.addProperty("shrinkRuns", f.shrinkRuns());
        o.add("kept", GSON.toJsonTree(kept(f.shrunk())));
        o.addProperty("reproduce", "./emini fuzz --replay " + json + "   (or: ./emini fuzz --seed " + r.seed + " --only "
                + r.profile.name().toLowerCase() + ":" + r.index + ")");
        List<String> why = SceneText.inexpressible(f.shrunk());
        o.addProperty("scene", why.isEmpty() ? name + ".yaml" : "none: a scene cannot hold " + String.join(", ", why));
        o.add("recipe", GSON.toJsonTree(f.shrunk()));
        Files.writeString(json, GSON.toJson(o), StandardCharsets.UTF_8);
        if (why.isEmpty()) {
            List<String> comments = new ArrayList<>();
            comments.add("Found by ./emini fuzz: " + f.shrunkViolation());
            comments.add("World " + r.index + " of seed " + r.seed + " (" + r.profile + "), shrunk from " + r.summary());
            comments.add("Replay: ./emini fuzz --replay " + json);
            Files.writeString(dir.resolve(name + ".yaml"), SceneText.yaml(f.shrunk(), comments, expectations(f)),
                    StandardCharsets.UTF_8);
        }
        return json;
    }

    /** The kept element ids, by list. */
    static Map<String, List<Integer>> kept(Recipe r) {
        Map<String, List<Integer>> kept = new TreeMap<>();
        for (ElementRef ref : RecipeEdit.parts(r)) {
            kept.computeIfAbsent(ref.list(), k -> new ArrayList<>()).add(ref.id());
        }
        return kept;
    }

    /** An expectation the scene fails the way the world does, where the scene language has one. */
    private static List<Map<String, Object>> expectations(Finding f) {
        Map<String, Object> e = new LinkedHashMap<>();
        Violation v = f.shrunkViolation();
        String why = "world fuzzer: " + v.kind().label();
        switch (v.kind()) {
            case EXCEPTION, NON_FINITE -> e.put("stable", new LinkedHashMap<>());
            case ENERGY -> e.put("stable", Map.of("maxEnergyRise", bound(v.message())));
            case OVERLAP -> {
                e.put("metric", "penetration.max");
                e.put("of", "max");
                e.put("atMost", OverlapCheck.BOUND);
            }
            default -> {
                return List.of();
            }
        }
        e.put("why", why + " (" + v.message().replace('"', '\'') + ")");
        return List.of(e);
    }

    private static double bound(String message) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\(bound ([0-9.eE+-]+)").matcher(message);
        return m.find() ? Double.parseDouble(m.group(1)) : 0;
    }
}
