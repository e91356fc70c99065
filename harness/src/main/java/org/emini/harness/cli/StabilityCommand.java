package org.emini.harness.cli;

import com.google.gson.GsonBuilder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import org.emini.harness.sweep.EngineBackend;
import org.emini.harness.sweep.OracleBackend;
import org.emini.harness.sweep.StabilityFamily;
import org.emini.harness.sweep.StabilityMap;
import org.emini.harness.sweep.StabilityMapImage;
import org.emini.harness.sweep.SweepBackend;
import org.emini.harness.sweep.SweepGrid;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Option;

/** {@code stability}: stability maps (parameter against timestep) of stiff and extreme families. */
@Command(name = "stability", mixinStandardHelpOptions = true,
        description = "Stability maps: for each stiff or extreme family, parameter against timestep, stable or not, engine beside oracle.")
final class StabilityCommand implements Callable<Integer> {
    @Mixin
    Library library;

    @Spec
    CommandSpec spec;

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

    @Option(names = "--engines", paramLabel = "NAME,...", split = ",", defaultValue = "emini,pymunk,box2d",
            description = "Backends (default: ${DEFAULT-VALUE}); an oracle that cannot be set up has maps that say why.")
    List<String> engines;

    @Option(names = "--progress", negatable = true, description = "Show a progress bar (default: when the output is a terminal).")
    Boolean progress;

    @Mixin
    OracleOptions oracle;

    @Override
    public Integer call() throws Exception {
        SweepGrid grid = Options.grid(spec, rates, List.of(iterations));
        List<StabilityFamily> chosen = new ArrayList<>();
        for (StabilityFamily f : StabilityFamily.all()) {
            if (families == null || families.contains(f.name())) {
                chosen.add(f);
            }
        }
        List<String> known = StabilityFamily.all().stream().map(StabilityFamily::name).toList();
        for (String f : families == null ? List.<String>of() : families) {
            Options.require(spec, known.contains(f), "--families: unknown family " + f + " (" + String.join(", ", known) + ")");
        }
        for (String e : engines) {
            Options.require(spec, e.equals("emini") || OracleOptions.ENGINES.contains(e),
                    "--engines: unknown engine " + e + " (emini, pymunk, box2d)");
        }
        List<SweepBackend> backends = new ArrayList<>();
        List<OracleBackend> oracles = new ArrayList<>();
        for (String e : engines) {
            switch (e) {
                case "emini" -> backends.add(new EngineBackend(library.loader()));
                default -> {
                    OracleBackend o = oracle.backend(library, reports.resolve(e.equals("pymunk") ? "oracle-serve.log"
                            : "oracle-serve-" + e + ".log"), e);
                    oracles.add(o);
                    backends.add(o);
                }
            }
        }
        try {
            return maps(grid, chosen, backends, oracles);
        } finally {
            for (OracleBackend o : oracles) {
                o.close();
            }
        }
    }

    private int maps(SweepGrid grid, List<StabilityFamily> chosen, List<SweepBackend> backends, List<OracleBackend> oracles)
            throws Exception {
        for (OracleBackend o : oracles) {
            if (o.unavailable() != null) {
                System.err.println("stability: " + o.name() + " skipped: " + o.unavailable());
            }
        }
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
                String image = "maps/" + f.name() + ".svg";
                StabilityMapImage.write(reports.resolve(image), f, grid.rates(), iterations, maps);
                fam.put("image", image);
                out.add(fam);
                StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "stability %-16s", f.name()));
                for (StabilityMap.Map m : maps) {
                    long stable = m.cells().stream().filter(c -> c.verdict().equals("stable")).count();
                    line.append(String.format(Locale.ROOT, "  %s %d/%d stable", m.engine(), stable, m.cells().size()));
                    m.cells().stream().filter(c -> c.verdict().equals("unsupported") || c.verdict().equals("error"))
                            .findFirst().ifPresent(c -> line.append(" (").append(c.verdict()).append(": ").append(c.detail()).append(")"));
                    if (!m.note().isEmpty()) {
                        line.append(" (").append(m.note()).append(")");
                    }
                }
                System.out.println(line);
                if (pb != null) {
                    pb.step();
                }
            }
        }
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("format", "emini-stability");
        doc.put("version", 1);
        doc.put("engines", backends.stream().map(SweepBackend::name).toList());
        if (!oracles.isEmpty()) {
            doc.put("oracle", String.join("; ", oracles.stream().map(o -> o.unavailable() == null ? o.versions()
                    : o.unavailable()).toList()));
        }
        doc.put("families", out);
        Files.createDirectories(reports);
        Files.writeString(reports.resolve("stability.json"),
                new GsonBuilder().setPrettyPrinting().serializeSpecialFloatingPointValues().create().toJson(doc), StandardCharsets.UTF_8);
        System.out.println("stability: " + reports.resolve("stability.json") + ", images in " + reports.resolve("maps"));
        return 0;
    }
}
