package org.emini.io;

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

    /** The folder; skips the calling test with a clear message when it is absent. */
    static Path require() {
        Path folder = folder();
        assumeTrue(folder != null, "reference worlds not found: expected ../shared/reference/worlds beside the "
                + "repository (or -Demini.worlds=DIR); skipping the tests on the original's files");
        return folder;
    }

    static byte[] bytes(String name) {
        try {
            return Files.readAllBytes(require().resolve(name));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Every file in the folder, sorted by name; empty when the folder is absent. */
    static List<Path> all() {
        Path folder = folder();
        List<Path> files = new ArrayList<>();
        if (folder != null) {
            try (Stream<Path> s = Files.list(folder)) {
                s.filter(Files::isRegularFile).sorted().forEach(files::add);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return files;
    }

    static PhyWorld read(String name) throws PhyFormatException {
        return new PhyReader().read(bytes(name));
    }
}
