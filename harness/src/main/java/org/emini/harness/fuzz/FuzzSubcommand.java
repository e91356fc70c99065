package org.emini.harness.fuzz;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.emini.harness.cli.ExitStatus;
import org.emini.harness.cli.Library;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** What the fuzz subcommands share: options, checks of them, the run and its exit status. */
abstract class FuzzSubcommand implements Callable<Integer> {
    @Mixin
    Library library;

    @Mixin
    FuzzOptions options;

    @Spec
    CommandSpec spec;

    /** The target, with its corpus read. */
    abstract FuzzTarget target() throws Exception;

    @Override
    public Integer call() throws Exception {
        require(options.count >= 0 && options.from >= 0, "--count and --from must be at least 0");
        require(options.timeout >= 1, "--timeout must be at least 1 s");
        require(options.ticks >= 0 && options.ticks <= 1000, "--ticks must be in 0..1000");
        FuzzTarget target = target();
        Path out = options.out != null ? options.out : Path.of("reports", "fuzz", target.name());
        FuzzRun.Result r = FuzzRun.run(target, options, library.schemaFile(), out, System.out);
        return r.failures(null) > 0 ? ExitStatus.FINDINGS : ExitStatus.OK;
    }

    void require(boolean condition, String message) {
        if (!condition) {
            throw new ParameterException(spec.commandLine(), message);
        }
    }
}
