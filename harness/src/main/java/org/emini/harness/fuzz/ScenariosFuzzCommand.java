package org.emini.harness.fuzz;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.emini.harness.load.ScenarioFiles;
import picocli.CommandLine.Command;

/** {@code fuzz scenarios}: the scene loader on mutants of the library's scene files. */
@Command(name = "scenarios", mixinStandardHelpOptions = true,
        description = "Fuzzes the scene loader (validate, then a few ticks of what it accepts) with mutants of the "
                + "library's scene files: byte flips, cuts, extreme and misread numbers, lost and repeated keys, "
                + "alias bombs, deep nesting, invalid UTF-8.")
final class ScenariosFuzzCommand extends FuzzSubcommand {
    @Override
    FuzzTarget target() throws Exception {
        List<byte[]> corpus = new ArrayList<>();
        for (Path f : ScenarioFiles.expand(List.of(library.root()))) {
            if (!ScenarioFiles.isWorldFile(f)) {
                corpus.add(Files.readAllBytes(f));
            }
        }
        return new FuzzTarget("scenarios", "yaml", corpus);
    }
}
