package org.emini.harness.load;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.emini.harness.convert.WorldToScenario;
import org.emini.harness.scenario.Scenario;
import org.emini.io.PhyFormatException;
import org.emini.io.PhyReader;
import org.emini.io.PhyWorld;

/**
 * Reads scenario files: parse (YAML or JSON), validate against the schema, then read into a
 * {@link Scenario}. Every failure comes back as located {@link Problem}s, never as an exception.
 */
public final class ScenarioLoader {
    private final SchemaCheck schema;
    private final Path libraryRoot;

    /**
     * @param schema the schema check
     * @param libraryRoot the scenarios/ folder: scene ids are file paths relative to it
     */
    public ScenarioLoader(SchemaCheck schema, Path libraryRoot) {
        this.schema = schema;
        this.libraryRoot = libraryRoot.toAbsolutePath().normalize();
    }

    /** A loaded scene or the problems found. */
    public record Loaded(Path file, Scenario scenario, List<Problem> problems) {
        /** Whether the scene is valid. */
        public boolean ok() {
            return scenario != null;
        }
    }

    /**
     * Loads a file. An original world file (.phy, .world) is converted as {@code convert} does, with
     * a run of {@link #WORLD_FILE_SECONDS} and the expectation that it stays stable.
     */
    public Loaded load(Path file) {
        String shown = shown(file);
        String text;
        try {
            text = ScenarioFiles.isWorldFile(file) ? worldFileScene(file) : Files.readString(file, StandardCharsets.UTF_8);
        } catch (PhyFormatException e) {
            return new Loaded(file, null, List.of(new Problem(shown, 0, 0, "$", "not a valid world file: " + e.getMessage())));
        } catch (IOException e) {
            return new Loaded(file, null, List.of(new Problem(shown, 0, 0, "$", "cannot read: " + e.getMessage())));
        }
        return load(shown, text, defaultName(file));
    }

    /** Run length of a world file read as a scene: 600 ticks at the original's 20 ticks per second. */
    public static final double WORLD_FILE_SECONDS = 30;

    /** A world file as scene text (what {@code convert} writes). */
    public static String worldFileScene(Path file) throws IOException {
        PhyWorld doc = new PhyReader().read(Files.readAllBytes(file));
        return WorldToScenario.convert(doc, file.getFileName().toString(), WORLD_FILE_SECONDS).yaml();
    }

    /** Loads text (for tests and tools); {@code name} is the scene id when the text gives none. */
    public Loaded load(String shown, String text, String name) {
        DocumentParser.Parsed parsed = DocumentParser.parse(shown, text);
        if (!parsed.ok()) {
            return new Loaded(Path.of(shown), null, parsed.problems());
        }
        List<Problem> problems = schema.check(shown, parsed.root(), parsed.sourceMap());
        if (!problems.isEmpty()) {
            return new Loaded(Path.of(shown), null, problems);
        }
        ScenarioReader reader = new ScenarioReader(shown, parsed.sourceMap());
        Scenario scenario = reader.read(parsed.root(), name);
        return new Loaded(Path.of(shown), scenario, reader.problems());
    }

    /** The scene id: the path under the library without extension, or the file name elsewhere. */
    String defaultName(Path file) {
        Path abs = file.toAbsolutePath().normalize();
        Path rel = abs.startsWith(libraryRoot) ? libraryRoot.relativize(abs) : abs.getFileName();
        String s = rel.toString().replace('\\', '/');
        int dot = s.lastIndexOf('.');
        return dot > 0 ? s.substring(0, dot) : s;
    }

    private static String shown(Path file) {
        Path cwd = Path.of("").toAbsolutePath();
        Path abs = file.toAbsolutePath().normalize();
        return abs.startsWith(cwd) ? cwd.relativize(abs).toString() : abs.toString();
    }
}
