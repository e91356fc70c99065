package org.emini.harness.cli;

import com.google.gson.GsonBuilder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import org.emini.harness.sweep.EngineBackend;
import org.emini.harness.sweep.OracleBackend;
import org.emini.harness.sweep.StabilityFamily;
import org.emini.harness.sweep.StabilityMap;
import org.emini.harness.sweep.SweepBackend;
import org.emini.harness.sweep.SweepGrid;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code stability}: stability maps (parameter against timestep) of stiff and extreme families. */
@Command(name = "stability", mixinStandardHelpOptions = true,
        description = "Stability maps: for each stiff or extreme family, parameter against timestep, stable or not, engine beside oracle.")
final class StabilityCommand implements Callable<Integer> {
    @Mixin
    Library library;

    @Option(names = "--reports", paramLabel = "DIR", defaultValue = "reports/stability",
            description = "Where stability.json goes (default: ${DEFAULT-VALUE}).")
    Path reports;

    @Option(names = "--families", paramLabel = "NAME,...", split = ",",
            description = "Families to map (default: all: massRatio, stackHeight, bodySpeed, distance, bodySize, springStiffness).")
    List<String> families;

    @Option(names = "--rates", paramLabel = "FROM..TO", defaultValue = "15..960",
            description = "Ticks per second, doubling (default: ${DEFAULT-VALUE}).")
    String rates;

    @Option(names = "--iterations", paramLabel = "N", defaultValue = "10", description = "Solver iterations (default: ${DEFAULT-VALUE}).")
    int iterations;

    @Option(names = "--progress", negatable = true, description = "Show a progress bar (default: when the output is a terminal).")
    Boolean progress;

    @Override
    public Integer call() throws Exception {
        String[] r = rates.split("\\.\\.");
        SweepGrid grid = SweepGrid.of(Integer.parseInt(r[0].trim()), Integer.parseInt(r[r.length - 1].trim()), List.of(iterations));
        List<StabilityFamily> chosen = new ArrayList<>();
        for (StabilityFamily f : StabilityFamily.all()) {
            if (families == null || families.contains(f.name())) {
                chosen.add(f);
            }
        }
        List<SweepBackend> backends = List.of(new EngineBackend(library.loader()), new OracleBackend());
        List<Object> out = new ArrayList<>();
        boolean bar = progress != null ? progress : System.console() != null;
        try (ProgressBar pb = bar ? new ProgressBarBuilder().setTaskName("families").setInitialMax(chosen.size())
                .setConsumer(new ConsoleProgressBarConsumer(System.err)).build() : null) {
            for (StabilityFamily f : chosen) {
                Map<String, Object> fam = new LinkedHashMap<>();
                fam.put("family", f.name());
                fam.put("parameter", f.parameter());
                fam.put("why", f.why());
                fam.put("values", f.values());
                fam.put("rates", grid.rates());
                fam.put("iterations", iterations);
                List<StabilityMap.Map> maps = new ArrayList<>();
                for (SweepBackend b : backends) {
                    maps.add(StabilityMap.run(f, b, grid.rates(), iterations));
                }
                fam.put("maps", maps);
                out.add(fam);
                StabilityMap.Map engine = maps.get(0);
                long stable = engine.cells().stream().filter(c -> c.verdict().equals("stable")).count();
                System.out.printf("stability %-16s emini %d/%d cells stable%s%n", f.name(), stable, engine.cells().size(),
                        engine.cells().stream().anyMatch(c -> c.verdict().equals("unsupported")) ? " (unsupported: " + engine.cells().get(0).detail() + ")" : "");
                if (pb != null) {
                    pb.step();
                }
            }
        }
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("format", "emini-stability");
        doc.put("version", 1);
        doc.put("families", out);
        Files.createDirectories(reports);
        Files.writeString(reports.resolve("stability.json"),
                new GsonBuilder().setPrettyPrinting().serializeSpecialFloatingPointValues().create().toJson(doc), StandardCharsets.UTF_8);
        System.out.println("stability: " + reports.resolve("stability.json"));
        return 0;
    }
}
