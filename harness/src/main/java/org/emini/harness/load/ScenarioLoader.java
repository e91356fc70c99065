package org.emini.harness.load;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.emini.harness.build.BuildRefusedException;
import org.emini.harness.build.UnsupportedElementException;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.build.WorldLimits;
import org.emini.harness.convert.WorldToScenario;
import org.emini.world.World;
import org.emini.harness.scenario.BodySpec;
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

    /** How a problem that is a defect (of the harness or the engine), not a fault of the file, begins. */
    public static final String INTERNAL_ERROR = "internal error building the world: ";

    /** A loaded scene or the problems found. */
    public record Loaded(Path file, Scenario scenario, List<Problem> problems) {
        /** Whether the scene is valid. */
        public boolean ok() {
            return scenario != null;
        }
    }

    /**
     * Loads a file. An original world file (.phy, .world) is converted as {@code convert} does, with
     * a run of {@link #WORLD_FILE_SECONDS} and the expectation that it stays stable, and what its
     * expectations file beside it adds ({@link WorldExpectations}).
     */
    public Loaded load(Path file) {
        String shown = shown(file);
        if (ScenarioFiles.isWorldFile(file)) {
            return loadWorldFile(file, shown);
        }
        byte[] bytes;
        try {
            // Checked before reading, so that a huge file is refused without being read.
            if (Files.size(file) > Limits.FILE_BYTES) {
                return new Loaded(file, null, List.of(new Problem(shown, 0, 0, "$", "the file is " + Files.size(file)
                        + " bytes, more than the " + Limits.FILE_BYTES + " a scene may have")));
            }
            bytes = Files.readAllBytes(file);
        } catch (IOException e) {
            return new Loaded(file, null, List.of(new Problem(shown, 0, 0, "$", "cannot read: " + IoText.describe(e))));
        }
        Loaded loaded = load(shown, bytes, defaultName(file));
        return new Loaded(file, loaded.scenario(), loaded.problems());
    }

    /** Loads a scene file's bytes (for tools such as the fuzzer); {@code name} as in {@link #load(String, String, String)}. */
    public Loaded load(String shown, byte[] bytes, String name) {
        SceneText.Decoded text = SceneText.decode(shown, bytes);
        if (text.problem() != null) {
            return new Loaded(Path.of(shown), null, List.of(text.problem()));
        }
        return load(shown, text.text(), name);
    }

    /**
     * A world file read as the scene {@code convert} makes of it. Problems found in that scene name
     * its path but no line: the lines would be the generated text's, not the file's.
     */
    private Loaded loadWorldFile(Path file, String shown) {
        String text;
        try {
            text = worldFileScene(file);
        } catch (PhyFormatException e) {
            return new Loaded(file, null, List.of(new Problem(shown, 0, 0, "$", "not a valid world file: " + e.getMessage())));
        } catch (IOException e) {
            return new Loaded(file, null, List.of(new Problem(shown, 0, 0, "$", "cannot read: " + IoText.describe(e))));
        }
        Loaded loaded = load(shown, text, defaultName(file));
        List<Problem> problems = new ArrayList<>();
        for (Problem p : loaded.problems()) {
            problems.add(new Problem(p.file(), 0, 0, p.path(), "in the scene converted from it: " + p.message()));
        }
        return new Loaded(file, loaded.scenario(), problems);
    }

    /** Run length of a world file read as a scene: 600 ticks at the original's 20 ticks per second. */
    public static final double WORLD_FILE_SECONDS = 30;

    /** A world file as scene text (what {@code convert} writes). */
    public static String worldFileScene(Path file) throws IOException {
        PhyWorld doc = new PhyReader().read(Files.readAllBytes(file));
        String yaml = WorldToScenario.convert(doc, file.getFileName().toString(), WORLD_FILE_SECONDS).yaml();
        Path sidecar = ScenarioFiles.expectationsOf(file);
        return Files.isRegularFile(sidecar) ? WorldExpectations.merge(yaml, sidecar) : yaml;
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
        if (scenario == null) {
            return new Loaded(Path.of(shown), null, reader.problems());
        }
        Problem refused = buildProblem(shown, scenario, parsed.sourceMap());
        return refused == null ? new Loaded(Path.of(shown), scenario, List.of())
                : new Loaded(Path.of(shown), null, List.of(refused));
    }

    /**
     * Builds the scene's world, as {@code run} will, so that a valid scene is one the engine accepts:
     * the engine's own checks, located where the scene writes the refused value. An element the engine
     * lacks is a run's {@code unsupported}, not a fault of the file.
     */
    private static Problem buildProblem(String shown, Scenario scenario, SourceMap sourceMap) {
        try {
            return startProblem(shown, scenario, WorldBuilder.build(scenario).world(), sourceMap);
        } catch (BuildRefusedException e) {
            int[] at = sourceMap.locate(e.path());
            return new Problem(shown, at[0], at[1], e.path().toString(), "the engine refuses it: " + e.getMessage());
        } catch (UnsupportedElementException e) {
            return null;
        } catch (RuntimeException e) {
            // Not a value the engine refused with a reason: a defect, shown as such (and found by harness fuzz).
            return new Problem(shown, 0, 0, "$", INTERNAL_ERROR + e);
        }
    }

    /** The starting world against the limits that need it built: positions, overlapping pairs. */
    private static Problem startProblem(String shown, Scenario scenario, World world, SourceMap sourceMap) {
        int far = WorldLimits.farBody(world);
        if (far >= 0) {
            return located(shown, scenario.bodies().get(far), sourceMap, "body '" + scenario.bodies().get(far).name()
                    + "' " + WorldLimits.far(world.getBody(far)));
        }
        WorldLimits.Overlaps o = WorldLimits.startingOverlaps(world);
        if (o.tooMany()) {
            BodySpec worst = scenario.bodies().get(o.worst());
            return located(shown, worst, sourceMap, (o.counted() ? "more than " + Limits.STARTING_OVERLAPS
                    + " pairs of bodies overlap at the start (bounding boxes)" : "too many bodies share both an x and "
                    + "a y range to count their overlaps") + ", more than the engine can collide at once; body '"
                    + worst.name() + "' meets the most");
        }
        return null;
    }

    private static Problem located(String shown, BodySpec body, SourceMap sourceMap, String message) {
        int[] at = sourceMap.locate(body.path());
        return new Problem(shown, at[0], at[1], body.path().toString(), message);
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
