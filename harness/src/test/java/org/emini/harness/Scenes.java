package org.emini.harness;

import java.nio.file.Path;
import org.emini.harness.load.Problem;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import org.emini.harness.scenario.Scenario;

/** Loads scenes from text in tests. */
public final class Scenes {
    private static SchemaCheck schema;

    private Scenes() {
    }

    /** The library's loader (schema read once). */
    public static synchronized ScenarioLoader loader() {
        if (schema == null) {
            schema = SchemaCheck.fromFile(Repo.schema());
        }
        return new ScenarioLoader(schema, Repo.scenarios());
    }

    /** Loads text as a file of that name. */
    public static ScenarioLoader.Loaded load(String file, String... lines) {
        return loader().load(file, String.join("\n", lines) + "\n", stem(file));
    }

    /** Loads text that must be valid. */
    public static Scenario valid(String file, String... lines) {
        ScenarioLoader.Loaded loaded = load(file, lines);
        if (!loaded.ok()) {
            throw new AssertionError("expected a valid scene, got " + loaded.problems());
        }
        return loaded.scenario();
    }

    /** The one problem of a scene that must be refused for exactly one reason. */
    public static Problem onlyProblem(ScenarioLoader.Loaded loaded) {
        if (loaded.ok() || loaded.problems().size() != 1) {
            throw new AssertionError("expected exactly one problem, got " + (loaded.ok() ? "a valid scene" : loaded.problems()));
        }
        return loaded.problems().get(0);
    }

    private static String stem(String file) {
        String n = Path.of(file).getFileName().toString();
        return n.contains(".") ? n.substring(0, n.lastIndexOf('.')) : n;
    }
}
