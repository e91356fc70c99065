package org.emini.harness.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.emini.harness.dashboard.DashboardWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code dashboard}: writes reports/index.html from what run, compare, sweep and stability left there. */
@Command(name = "dashboard", mixinStandardHelpOptions = true,
        description = "Writes the static dashboard (index.html and dashboard/) into the reports folder.")
final class DashboardCommand implements Callable<Integer> {
    @Mixin
    Library library;

    @Option(names = "--reports", paramLabel = "DIR", defaultValue = "reports",
            description = "The reports folder to read and write (default: ${DEFAULT-VALUE}).")
    Path reports;

    @Override
    public Integer call() throws Exception {
        Path index = new DashboardWriter(reports, library.loader(), library.root()).write();
        System.out.println("dashboard: " + index.toAbsolutePath().toUri());
        return 0;
    }
}
