package org.emini.harness.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.emini.harness.load.Problem;
import org.emini.harness.load.ScenarioFiles;
import org.emini.harness.load.ScenarioLoader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Parameters;

/** {@code validate PATHS}: checks scene files against the schema and the reader's rules. */
@Command(name = "validate", mixinStandardHelpOptions = true,
        description = "Checks scenario files (or folders of them); prints file:line:column: path: problem.")
final class ValidateCommand implements Callable<Integer> {
    @Mixin
    Library library;

    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "PATHS", arity = "0..*", description = "Scene files or folders (default: the library).")
    List<Path> paths;

    @Override
    public Integer call() {
        ScenarioLoader loader = library.loader();
        List<Path> files = library.files(spec, paths);
        int invalid = 0;
        for (Path file : files) {
            ScenarioLoader.Loaded loaded = loader.load(file);
            if (!loaded.ok()) {
                invalid++;
                for (Problem p : loaded.problems()) {
                    System.out.println(p);
                }
            }
        }
        System.out.println(files.size() + " scene files: " + (files.size() - invalid) + " valid, " + invalid + " invalid");
        return invalid == 0 ? 0 : 1;
    }
}
