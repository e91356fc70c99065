package org.emini.bench.scene;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import org.emini.harness.scenario.Scenario;

/**
 * Finds and loads benchmark scenes from the scenario library with the harness's loader (schema check
 * included), by scene id ({@code bench/pyramid-20}).
 */
public final class BenchScenes {
    private final Path root;
    private final ScenarioLoader loader;

    private BenchScenes(Path root) {
        this.root = root;
        Path lib = root.resolve("scenarios");
        this.loader = new ScenarioLoader(SchemaCheck.fromFile(lib.resolve("scenario.schema.json")), lib);
    }

    /**
     * The repository root: the system property {@code emini.root}, else the first folder upward from
     * the working directory that holds {@code scenarios/scenario.schema.json}.
     */
    public static Path findRoot() {
        String prop = System.getProperty("emini.root");
        if (prop != null) {
            return Path.of(prop).toAbsolutePath().normalize();
        }
        for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
            if (Files.isRegularFile(dir.resolve("scenarios").resolve("scenario.schema.json"))) {
                return dir;
            }
        }
        throw new IllegalStateException("cannot find scenarios/scenario.schema.json here or above; set -Demini.root");
    }

    /** The library of the repository found by {@link #findRoot()}. */
    public static BenchScenes open() {
        return new BenchScenes(findRoot());
    }

    /** The repository root. */
    public Path root() {
        return root;
    }

    /** The file of a scene id, or null when there is none (yet). */
    public Path file(String id) {
        for (String ext : List.of(".yaml", ".yml", ".json")) {
            Path f = root.resolve("scenarios").resolve(id + ext);
            if (Files.isRegularFile(f)) {
                return f;
            }
        }
        return null;
    }

    /** Loads a scene; an invalid file is an error naming its problems. */
    public Scenario load(String id) {
        Path f = file(id);
        if (f == null) {
            throw new IllegalArgumentException("no scene file for " + id + " under " + root.resolve("scenarios"));
        }
        ScenarioLoader.Loaded l = loader.load(f);
        if (!l.ok()) {
            throw new IllegalArgumentException("invalid scene " + id + ": "
                + l.problems().stream().map(Object::toString).collect(Collectors.joining("; ")));
        }
        return l.scenario();
    }
}
