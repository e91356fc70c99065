package org.emini.harness.load;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/** Expands the PATHS of a command (files and folders) into scene files, sorted within each folder. */
public final class ScenarioFiles {
    private ScenarioFiles() {
    }

    /**
     * Whether a file name is a scene (YAML or JSON, but not the schema, a world file's expectations,
     * {@code *.expect.yaml}, nor a stored trace, {@code *.trace.json}, that expectations compare with) or an
     * original world file.
     */
    public static boolean isScene(Path file) {
        String n = file.getFileName().toString();
        return (n.endsWith(".yaml") || n.endsWith(".yml") || n.endsWith(".json")) && !n.endsWith(".schema.json")
            && !n.endsWith(EXPECT_SUFFIX) && !n.endsWith(TRACE_SUFFIX) || isWorldFile(file);
    }

    /** The suffix of a trace file ({@code harness run} writes them; a scene may keep one as its reference). */
    public static final String TRACE_SUFFIX = ".trace.json";

    /** The suffix of the expectations file beside a world file: {@code level.phy} has {@code level.expect.yaml}. */
    public static final String EXPECT_SUFFIX = ".expect.yaml";

    /** The expectations file beside a world file ({@code level.expect.yaml} for {@code level.phy}), whether or not it exists. */
    public static Path expectationsOf(Path worldFile) {
        String n = worldFile.getFileName().toString();
        int dot = n.lastIndexOf('.');
        return worldFile.resolveSibling((dot > 0 ? n.substring(0, dot) : n) + EXPECT_SUFFIX);
    }

    /** Whether a file is an original World Designer file (.phy, .world), read through {@code convert}. */
    public static boolean isWorldFile(Path file) {
        String n = file.getFileName().toString().toLowerCase(java.util.Locale.ROOT);
        return n.endsWith(".phy") || n.endsWith(".world");
    }

    /**
     * The scene files under the given paths. A named file is taken as it is (a typo is reported by the
     * loader); folders are searched recursively.
     */
    public static List<Path> expand(List<Path> paths) {
        List<Path> out = new ArrayList<>();
        for (Path p : paths) {
            if (Files.isDirectory(p)) {
                try (Stream<Path> walk = Files.walk(p)) {
                    walk.filter(Files::isRegularFile).filter(ScenarioFiles::isScene).sorted().forEach(out::add);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            } else {
                out.add(p);
            }
        }
        return out;
    }
}
