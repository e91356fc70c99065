package org.emini.harness.cli;

import org.emini.harness.fuzz.FuzzCommand;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The harness command line: {@code validate} and {@code run} over scenario files and folders,
 * {@code compare} with the pymunk oracle, {@code expand} (scenes as the harness reads them) and
 * {@code convert} between original world files and scene files, and {@code fuzz}: the world fuzzer
 * ({@code fuzz worlds}) and the loaders' ({@code fuzz scenarios|phy|setters}).
 */
@Command(name = "harness", mixinStandardHelpOptions = true, version = "emini harness 0.1.0",
        description = "Runs Emini's scenario library: validation, metrics, expectations, traces and reports.",
        subcommands = {ValidateCommand.class, RunCommand.class, CompareCommand.class, ExpandCommand.class,
                SweepCommand.class, StabilityCommand.class, DashboardCommand.class, DiffCommand.class,
                ConvertCommand.class, FuzzCommand.class, FlavoursCommand.class, CommandLine.HelpCommand.class})
public final class Main implements Runnable {

    @Override
    public void run() {
        new CommandLine(this).usage(System.out);
    }

    /** Runs the command line and exits with its status. */
    public static void main(String[] args) {
        System.exit(execute(args));
    }

    /** Runs the command line and returns its exit status (for tests). */
    public static int execute(String... args) {
        CommandLine cmd = new CommandLine(new Main());
        ExitStatus.describe(cmd);
        Failures failures = new Failures();
        cmd.setExecutionExceptionHandler(failures);
        cmd.setParameterExceptionHandler(failures);
        try {
            return cmd.execute(args);
        } catch (Error e) {
            // picocli hands on Errors (OutOfMemoryError, StackOverflowError): one line here too.
            CommandLine last = cmd.getParseResult() == null ? cmd : cmd.getParseResult().asCommandLineList()
                    .get(cmd.getParseResult().asCommandLineList().size() - 1);
            return Failures.report(e, last);
        }
    }
}
