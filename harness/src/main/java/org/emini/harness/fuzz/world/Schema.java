package org.emini.harness.fuzz.world;

import java.nio.file.Files;
import java.nio.file.Path;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;

/**
 * The scenario schema and a loader for scene text, found as the harness finds them: under
 * {@code emini.root} (the tests set it) or in scenarios/ in the working folder or above.
 */
final class Schema {
    private static ScenarioLoader loader;

    private Schema() {
    }

    static synchronized ScenarioLoader loader() {
        if (loader == null) {
            Path file = find();
            loader = new ScenarioLoader(SchemaCheck.fromFile(file), file.getParent());
        }
        return loader;
    }

    private static Path find() {
        String root = System.getProperty("emini.root");
        if (root != null && Files.exists(Path.of(root, "scenarios", "scenario.schema.json"))) {
            return Path.of(root, "scenarios", "scenario.schema.json");
        }
        for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
            Path candidate = dir.resolve("scenarios").resolve("scenario.schema.json");
            if (Files.exists(candidate)) {
                return candidate;
            }
        }
        throw new IllegalStateException("cannot find scenarios/scenario.schema.json here or above (or under -Demini.root)");
    }
}
