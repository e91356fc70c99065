package org.emini.harness;

import java.nio.file.Path;

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
}
