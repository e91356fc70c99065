package org.emini.harness;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Assertions;
import org.junit.jupiter.api.Assumptions;

/** Paths of the repository the tests run in (set by Surefire; falls back to the working directory's parent). */
public final class Repo {
    private Repo() {
    }

    /** The repository root. */
    public static Path root() {
        String root = System.getProperty("emini.root");
        return (root != null ? Path.of(root) : Path.of("..")).toAbsolutePath().normalize();
    }

    /** The scenario library. */
    public static Path scenarios() {
        return root().resolve("scenarios");
    }

    /** The scenario schema. */
    public static Path schema() {
        return scenarios().resolve("scenario.schema.json");
    }

    /**
     * The library's schema with an emitter key, {@code burst}, that no builder reads (a schema ahead of
     * the harness), written into {@code dir}: a valid scene that uses it has an element the engine lacks.
     */
    public static Path schemaAhead(Path dir) throws IOException {
        ObjectMapper json = new ObjectMapper();
        ObjectNode schema = (ObjectNode) json.readTree(schema().toFile());
        ((ObjectNode) schema.path("$defs").path("emitter").path("properties")).putObject("burst").put("type", "integer");
        Path file = Files.createDirectories(dir.resolve("schema")).resolve("scenario.schema.json");
        json.writeValue(file.toFile(), schema);
        return file;
    }

    /**
     * The original World Designer's files, {@code ../shared/reference/worlds} beside the repository (or
     * {@code -Demini.worlds=DIR}). When the folder is absent the calling test fails, unless the skip was
     * asked for (EMINI_SKIP_REFERENCE_WORLDS=1 or -Demini.skipReferenceWorlds=true): a test that passes
     * because its inputs are missing tests nothing.
     */
    public static Path referenceWorlds() {
        String override = System.getProperty("emini.worlds");
        Path dir = (override != null ? Path.of(override) : root().resolve("../shared/reference/worlds"))
                .toAbsolutePath().normalize();
        if (Files.isDirectory(dir)) {
            return dir;
        }
        String where = "reference worlds not found at " + dir;
        if ("1".equals(System.getenv("EMINI_SKIP_REFERENCE_WORLDS")) || Boolean.getBoolean("emini.skipReferenceWorlds")) {
            Assumptions.abort(where + "; skipped as asked (EMINI_SKIP_REFERENCE_WORLDS)");
        }
        return Assertions.fail(where + "; to run without them, set EMINI_SKIP_REFERENCE_WORLDS=1");
    }
}
