package org.emini.io;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * The real world files made with the original World Designer, found in
 * {@code ../shared/reference/worlds} beside the repository (or the folder named by the system
 * property {@code emini.worlds}).
 */
final class ReferenceWorlds {
    private ReferenceWorlds() {
    }

    /** The folder, or null when it is absent. */
    static Path folder() {
        String override = System.getProperty("emini.worlds");
        if (override != null) {
            return Files.isDirectory(Paths.get(override)) ? Paths.get(override) : null;
        }
        for (Path p = Paths.get("").toAbsolutePath(); p != null; p = p.getParent()) {
            Path candidate = p.resolve("shared/reference/worlds");
            if (Files.isDirectory(candidate)) {
                return candidate;
            }
        }
        return null;
    }

    /**
     * The folder. When it is absent the calling test fails, unless the skip was asked for: the
     * environment variable EMINI_SKIP_REFERENCE_WORLDS=1 or -Demini.skipReferenceWorlds=true. A test
     * that passes because its inputs are missing tests nothing.
     */
    static Path require() {
        Path folder = folder();
        if (folder != null) {
            return folder;
        }
        String where = "reference worlds not found: expected ../shared/reference/worlds beside the repository"
                + " (or -Demini.worlds=DIR)";
        if (skipAsked()) {
            assumeTrue(false, where + "; skipped as asked (EMINI_SKIP_REFERENCE_WORLDS)");
        }
        return fail(where + "; to run without them, set EMINI_SKIP_REFERENCE_WORLDS=1");
    }

    /** Whether the tests on the original's files may be skipped when the folder is absent. */
    static boolean skipAsked() {
        return "1".equals(System.getenv("EMINI_SKIP_REFERENCE_WORLDS"))
                || Boolean.getBoolean("emini.skipReferenceWorlds");
    }

    static byte[] bytes(String name) {
        try {
            return Files.readAllBytes(require().resolve(name));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Every file in the folder, sorted by name. When it is absent: empty if the skip was asked for
     * (tests over generated files still run; a test of a reference file skips in {@link #require}),
     * otherwise the calling test fails.
     */
    static List<Path> all() {
        if (folder() == null && skipAsked()) {
            return new ArrayList<>();
        }
        Path folder = require();
        List<Path> files = new ArrayList<>();
        try (Stream<Path> s = Files.list(folder)) {
            s.filter(Files::isRegularFile).sorted().forEach(files::add);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return files;
    }

    static PhyWorld read(String name) throws PhyFormatException {
        return new PhyReader().read(bytes(name));
    }
}
