package org.emini.harness.sweep;

import com.google.gson.Gson;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.yaml.snakeyaml.LoaderOptions;
import org.yaml.snakeyaml.Yaml;
import org.yaml.snakeyaml.constructor.SafeConstructor;

/**
 * A scene file rewritten for one point of a sweep: another timestep and iteration count, samples every
 * {@code every} seconds (a multiple of every swept timestep, so all points sample the same times), the
 * conservation metrics added and the expectations dropped (a sweep measures, it does not judge). The
 * result is scene text (JSON, which the YAML loader reads too), so the engine and the oracle read the
 * same variant.
 */
public final class SceneVariant {
    private static final List<String> CONSERVATION = List.of("energy", "linearMomentum", "angularMomentum", "stability");

    private SceneVariant() {
    }

    /**
     * Rewrites a scene.
     *
     * @param text the scene file's text (YAML or JSON)
     * @param name the scene id the variant keeps
     * @param timestep seconds per tick
     * @param iterations solver iterations
     * @param every sample interval (s)
     * @return the variant as JSON text
     */
    @SuppressWarnings("unchecked")
    public static String rewrite(String text, String name, double timestep, int iterations, double every) {
        Object doc = new Yaml(new SafeConstructor(new LoaderOptions())).load(text);
        if (!(doc instanceof Map)) {
            throw new IllegalArgumentException("a scene is a mapping, not " + doc);
        }
        Map<String, Object> scene = new LinkedHashMap<>((Map<String, Object>) doc);
        scene.put("name", name);
        Map<String, Object> world = new LinkedHashMap<>(map(scene.get("world")));
        world.remove("ticksPerSecond");
        world.put("timestep", timestep);
        world.put("iterations", iterations);
        scene.put("world", world);
        Map<String, Object> run = new LinkedHashMap<>(map(scene.get("run")));
        run.remove("expect");
        Map<String, Object> record = new LinkedHashMap<>(map(run.get("record")));
        record.put("every", every);
        List<Object> metrics = new ArrayList<>(record.get("metrics") instanceof List<?> l ? l : List.of());
        for (String m : CONSERVATION) {
            boolean present = metrics.stream().anyMatch(x -> m.equals(x) || (x instanceof Map<?, ?> mm && mm.containsKey(m)));
            if (!present) {
                metrics.add(m);
            }
        }
        record.put("metrics", metrics);
        run.put("record", record);
        scene.put("run", run);
        scene.remove("knownFailure");
        return new Gson().toJson(scene);
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> map(Object o) {
        return o instanceof Map ? (Map<String, Object>) o : Map.of();
    }
}
