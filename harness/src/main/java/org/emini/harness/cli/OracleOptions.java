package org.emini.harness.cli;

import java.nio.file.Path;
import org.emini.harness.oracle.OracleEnvironment;
import org.emini.harness.sweep.OracleBackend;
import picocli.CommandLine.Option;

/** Options of the commands that run the oracle (pymunk, Box2D v3): where it is and which Python builds its environment. */
final class OracleOptions {
    @Option(names = "--oracle-dir", paramLabel = "DIR",
            description = "The oracle's folder (default: oracle-py beside the scenarios folder).")
    Path oracleDir;

    @Option(names = "--python", paramLabel = "CMD",
            description = "The Python that creates the oracle's environment (default: $EMINI_PYTHON or python3).")
    String python;

    /** The oracle's folder. */
    Path home(Library library) {
        return oracleDir != null ? oracleDir : library.root().getParent().resolve("oracle-py");
    }

    /** The oracle's environment (created on first use). */
    OracleEnvironment environment(Library library) {
        return new OracleEnvironment(home(library), python != null ? python : OracleEnvironment.defaultPython());
    }

    /** A sweep backend running variants in pymunk, its process's stderr appended to {@code log}. */
    OracleBackend backend(Library library, Path log) {
        return backend(library, log, "pymunk");
    }

    /** A sweep backend running variants in an oracle engine (pymunk or box2d). */
    OracleBackend backend(Library library, Path log, String engine) {
        return new OracleBackend(environment(library), library.schemaFile(), log, System.err,
                OracleBackend.DEFAULT_TIMEOUT_SECONDS, engine);
    }

    /** The oracle engines: pymunk (Chipmunk 2D) and Box2D v3. */
    static final java.util.List<String> ENGINES = java.util.List.of("pymunk", "box2d");
}
