package org.emini.harness.fuzz;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.emini.harness.convert.ScenarioToWorld;
import org.emini.harness.load.ScenarioFiles;
import org.emini.harness.load.ScenarioLoader;
import org.emini.io.PhyWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fuzz phy}: the world-file readers on mutants of the original World Designer's files and of
 * the files the engine writes (the library's scenes converted, as {@code convert -o x.phy} does).
 */
@Command(name = "phy", mixinStandardHelpOptions = true,
        description = "Fuzzes the world-file readers (PhyReader, the engine's WorldBuilder, and harness run of a .phy) "
                + "with mutants of ../shared/reference/worlds and of the library converted to .phy.")
final class PhyFuzzCommand extends FuzzSubcommand {
    /** Library scenes larger than this are left out of the corpus: big files only slow the fuzzer down. */
    private static final int MAX_BODIES = 1000;

    @Option(names = "--worlds", paramLabel = "DIR",
            description = "The original's world files (default: shared/reference/worlds beside the repository).")
    Path worlds;

    @Override
    FuzzTarget target() throws Exception {
        List<byte[]> corpus = new ArrayList<>();
        Path dir = worlds != null ? worlds
                : library.root().toAbsolutePath().getParent().resolveSibling("shared").resolve("reference").resolve("worlds");
        if (Files.isDirectory(dir)) {
            try (Stream<Path> s = Files.list(dir)) {
                for (Path f : s.filter(ScenarioFiles::isWorldFile).sorted().toList()) {
                    corpus.add(Files.readAllBytes(f));
                }
            }
        } else {
            require(worlds == null, "--worlds " + worlds + ": no such folder");
            System.err.println("fuzz phy: no reference worlds at " + dir + "; fuzzing the engine's own files only");
        }
        ScenarioLoader loader = library.loader();
        for (Path f : ScenarioFiles.expand(List.of(library.root()))) {
            ScenarioLoader.Loaded l = loader.load(f);
            if (l.ok() && l.scenario().bodies().size() <= MAX_BODIES) {
                corpus.add(new PhyWriter().write(ScenarioToWorld.convert(l.scenario()).world()));
            }
        }
        return new FuzzTarget("phy", "phy", corpus);
    }
}
