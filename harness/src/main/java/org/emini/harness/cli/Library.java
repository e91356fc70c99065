package org.emini.harness.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.emini.harness.load.ScenarioFiles;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;

/** Options shared by the commands: where the schema (and so the scenario library) is. */
public final class Library {
    @picocli.CommandLine.Spec(picocli.CommandLine.Spec.Target.MIXEE)
    CommandSpec spec;

    @Option(names = "--schema", paramLabel = "FILE",
            description = "The scenario schema (default: scenarios/scenario.schema.json in this or a parent folder).")
    Path schema;

    /** The schema the jar carries, written to a temporary file on first use (outside a repository). */
    private static Path bundled;

    /**
     * The schema file: given, else found upward from the working directory, else the copy inside the
     * harness jar (the runnable jar used in another project's CI: scene ids are then relative to the
     * working directory).
     */
    public Path schemaFile() {
        if (schema != null) {
            return schema;
        }
        Path found = findUpward();
        return found != null ? found : bundledSchema();
    }

    private static Path findUpward() {
        for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
            Path candidate = dir.resolve("scenarios").resolve("scenario.schema.json");
            if (Files.isRegularFile(candidate)) {
                return candidate;
            }
        }
        return null;
    }

    private synchronized Path bundledSchema() {
        if (bundled == null) {
            try (java.io.InputStream in = SchemaCheck.class.getResourceAsStream("scenario.schema.json")) {
                if (in == null) {
                    throw new ParameterException(spec.commandLine(),
                            "cannot find scenarios/scenario.schema.json here or above; give --schema");
                }
                Path f = Files.createTempFile("emini-scenario-schema", ".json");
                f.toFile().deleteOnExit();
                Files.write(f, in.readAllBytes());
                bundled = f;
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        }
        return bundled;
    }

    /**
     * The library folder (the schema's folder): scene ids are paths relative to it; the working
     * directory when the schema is the jar's own.
     */
    public Path root() {
        Path s = schemaFile();
        return s.equals(bundled) ? Path.of("").toAbsolutePath() : s.toAbsolutePath().getParent();
    }

    /**
     * The scene files under PATHS (the library when none are given). A folder that holds none is a
     * usage error: a run of nothing must not pass.
     */
    public List<Path> files(CommandSpec spec, List<Path> paths) {
        List<Path> given = paths == null || paths.isEmpty() ? List.of(root()) : paths;
        for (Path p : given) {
            if (Files.isDirectory(p) && ScenarioFiles.expand(List.of(p)).isEmpty()) {
                throw new ParameterException(spec.commandLine(), "no scene files in " + p
                        + " (looked for *.yaml, *.yml, *.json, *.phy and *.world)");
            }
        }
        return ScenarioFiles.expand(given);
    }

    /** The library's loader. */
    public ScenarioLoader loader() {
        return new ScenarioLoader(SchemaCheck.fromFile(schemaFile()), root());
    }
}
