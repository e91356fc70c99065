package org.emini.harness.fuzz;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code fuzz}: the loaders under seeded, reproducible fuzzing. One subcommand per loader, each its own
 * class in this package; a new loader's fuzzer is one more class in {@code subcommands}.
 */
@Command(name = "fuzz", mixinStandardHelpOptions = true,
        description = {"Fuzzes the loaders: mutated inputs, each judged in a worker JVM with a time limit and a bounded "
                + "heap, counted as clean error, accepted, unlocated error, crash, hang or silent NaN.",
            "Failing inputs are written to --out as files that reproduce them; exit status 1 when there are any."},
        subcommands = {ScenariosFuzzCommand.class, PhyFuzzCommand.class, SettersFuzzCommand.class,
                CommandLine.HelpCommand.class})
public final class FuzzCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(System.out);
    }
}
