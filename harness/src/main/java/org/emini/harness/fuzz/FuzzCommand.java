package org.emini.harness.fuzz;

import org.emini.harness.fuzz.world.WorldFuzzCommand;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code fuzz}: seeded, reproducible fuzzing of the engine with random worlds ({@code worlds}) and of
 * the loaders (one subcommand per loader, each its own class in this package).
 */
@Command(name = "fuzz", mixinStandardHelpOptions = true,
        description = {"worlds: random worlds checked against invariants and metamorphic relations (harness/README.md).",
            "scenarios, phy, setters: fuzzes the loaders: mutated inputs, each judged in a worker JVM with a time limit and a bounded "
                + "heap, counted as clean error, accepted, unlocated error, crash, hang or silent NaN.",
            "Failing inputs are written to --out as files that reproduce them; exit status 1 when there are any."},
        subcommands = {WorldFuzzCommand.class, ScenariosFuzzCommand.class, PhyFuzzCommand.class, SettersFuzzCommand.class,
                CommandLine.HelpCommand.class})
public final class FuzzCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(System.out);
    }
}
