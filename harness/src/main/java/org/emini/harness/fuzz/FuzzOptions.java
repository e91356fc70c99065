package org.emini.harness.fuzz;

import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine.Option;

/** Options every fuzz subcommand shares. */
final class FuzzOptions {
    @Option(names = "--seed", paramLabel = "S", defaultValue = "1", description = "Seed (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--count", paramLabel = "N", defaultValue = "1000", description = "Inputs (default: ${DEFAULT-VALUE}).")
    long count;

    @Option(names = "--from", paramLabel = "I", defaultValue = "0",
            description = "First input index: --from I --count 1 runs input I of the seed again (default: ${DEFAULT-VALUE}).")
    long from;

    @Option(names = "--replay", paramLabel = "FILE", split = ",",
            description = "Judge these files (findings of an earlier run) instead of making inputs.")
    List<Path> replay;

    @Option(names = "--out", paramLabel = "DIR",
            description = "Where findings go (default: reports/fuzz/TARGET).")
    Path out;

    @Option(names = "--timeout", paramLabel = "SECONDS", defaultValue = "20",
            description = "Time limit per input; over it the input is a hang (default: ${DEFAULT-VALUE}).")
    int timeout;

    @Option(names = "--heap", paramLabel = "SIZE", defaultValue = "512m",
            description = "The worker JVM's heap (-Xmx; default: ${DEFAULT-VALUE}).")
    String heap;

    @Option(names = "--ticks", paramLabel = "N", defaultValue = "3",
            description = "Ticks of each accepted input (default: ${DEFAULT-VALUE}).")
    int ticks;
}
