package org.emini.harness.cli;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.emini.harness.flavour.FlavourReport;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code flavours}: the float engine and its double-precision flavour side by side (issue 19). */
@Command(name = "flavours", mixinStandardHelpOptions = true,
        description = "Writes flavours.md: both flavours' comparison rows against the truth, and their sweep points"
                + " (error and CPU cost).")
final class FlavoursCommand implements Callable<Integer> {
    @Option(names = "--float-compare", paramLabel = "DIR", defaultValue = "reports/compare",
            description = "The float engine's compare folder (default: ${DEFAULT-VALUE}).")
    Path floatCompare;

    @Option(names = "--double-compare", paramLabel = "DIR", defaultValue = "reports/flavours/compare",
            description = "The double flavour's compare folder (default: ${DEFAULT-VALUE}).")
    Path doubleCompare;

    @Option(names = "--sweep", paramLabel = "DIR", defaultValue = "reports/flavours/sweep",
            description = "A sweep folder with both flavours' points (default: ${DEFAULT-VALUE}).")
    Path sweep;

    @Option(names = "--out", paramLabel = "FILE", defaultValue = "reports/flavours/flavours.md",
            description = "The report (default: ${DEFAULT-VALUE}).")
    Path out;

    @Override
    public Integer call() throws Exception {
        String md = FlavourReport.markdown(Files.isDirectory(floatCompare) ? floatCompare : null,
                Files.isDirectory(doubleCompare) ? doubleCompare : null, Files.isDirectory(sweep) ? sweep : null);
        if (out.getParent() != null) {
            Files.createDirectories(out.getParent());
        }
        Files.writeString(out, md, StandardCharsets.UTF_8);
        System.out.println("flavours: " + out);
        return 0;
    }
}
