package org.emini.harness.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import picocli.CommandLine.Option;

/** Options shared by the commands: where the schema (and so the scenario library) is. */
final class Library {
    @Option(names = "--schema", paramLabel = "FILE",
            description = "The scenario schema (default: scenarios/scenario.schema.json in this or a parent folder).")
    Path schema;

    /** The schema file, found upward from the working directory when not given. */
    Path schemaFile() {
        if (schema != null) {
            return schema;
        }
        for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
            Path candidate = dir.resolve("scenarios").resolve("scenario.schema.json");
            if (Files.isRegularFile(candidate)) {
                return candidate;
            }
        }
        throw new IllegalStateException("cannot find scenarios/scenario.schema.json here or above; give --schema");
    }

    /** The library folder (the schema's folder): scene ids are paths relative to it. */
    Path root() {
        return schemaFile().toAbsolutePath().getParent();
    }

    ScenarioLoader loader() {
        return new ScenarioLoader(SchemaCheck.fromFile(schemaFile()), root());
    }
}
