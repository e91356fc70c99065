package org.emini.harness.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.sweep.EngineBackend;
import org.emini.harness.sweep.OracleBackend;
import org.emini.harness.sweep.PointStore;
import org.emini.harness.sweep.Sweep;
import org.emini.harness.sweep.SweepBackend;
import org.emini.harness.sweep.SweepGrid;
import org.emini.harness.sweep.SweepPoint;
import org.emini.harness.sweep.WorkPrecisionPlots;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code sweep PATHS}: error against cost over a grid of timesteps and iteration counts, for the engine
 * and the oracle; resumable (points already in the results file are skipped) and shardable.
 */
@Command(name = "sweep", mixinStandardHelpOptions = true,
        description = "Work-precision sweep: error and conservation drift against cost over timesteps and iterations.")
final class SweepCommand implements Callable<Integer> {
    @Mixin
    Library library;

    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "PATHS", arity = "1..*", description = "Scene files or folders.")
    List<Path> paths;

    @Option(names = "--reports", paramLabel = "DIR", defaultValue = "reports/sweep",
            description = "Where points.jsonl and the plots go (default: ${DEFAULT-VALUE}).")
    Path reports;

    @Option(names = "--results", paramLabel = "FILE",
            description = "The results file to resume and append to (default: DIR/points.jsonl).")
    Path results;

    @Option(names = "--shard", paramLabel = "K/N", defaultValue = "1/1",
            description = "Run only shard K of N (point i goes to shard i mod N + 1).")
    String shard;

    @Option(names = "--rates", paramLabel = "FROM..TO", defaultValue = "15..960",
            description = "Ticks per second, doubling from FROM up to TO (default: ${DEFAULT-VALUE}).")
    String rates;

    @Option(names = "--iterations", paramLabel = "N,N,...", split = ",", defaultValue = "2,5,10,20",
            description = "Iteration counts (default: ${DEFAULT-VALUE}).")
    List<Integer> iterations;

    @Option(names = "--repeats", paramLabel = "N", defaultValue = "3",
            description = "Runs per point; the cost is the best (default: ${DEFAULT-VALUE}).")
    int repeats;

    @Option(names = "--engines", paramLabel = "NAME,...", split = ",", defaultValue = "emini,pymunk,box2d",
            description = "Backends (default: ${DEFAULT-VALUE}). pymunk and box2d (Box2D v3) run in the oracle's environment"
                    + " (oracle-py/.venv, created on first use); if it cannot be set up the sweep says why and"
                    + " runs the others.")
    List<String> engines;

    @Mixin
    OracleOptions oracle;

    @Option(names = "--no-plots", description = "Do not draw the plots.")
    boolean noPlots;

    @Option(names = "--plot-cost", paramLabel = "wall|cpu", defaultValue = "cpu",
            description = "The plots' cost axis: the ticking thread's CPU time (default; steady on a busy machine) or wall time.")
    String plotCost;

    @Option(names = "--progress", negatable = true,
            description = "Show a progress bar (default: when the output is a terminal).")
    Boolean progress;

    @Override
    public Integer call() throws Exception {
        Options.require(spec, plotCost.equals("wall") || plotCost.equals("cpu"), "--plot-cost " + plotCost + ": wall or cpu");
        Options.atLeast(spec, "--repeats", repeats, 1);
        String[] kn = shard.split("/");
        int k;
        int n;
        try {
            k = Integer.parseInt(kn[0].trim());
            n = Integer.parseInt(kn[kn.length - 1].trim());
        } catch (NumberFormatException e) {
            throw new ParameterException(spec.commandLine(), "--shard " + shard + ": K/N, two whole numbers");
        }
        Options.require(spec, kn.length == 2 && n >= 1 && k >= 1 && k <= n, "--shard " + shard + ": K must be in 1..N");
        for (String e : engines) {
            Options.require(spec, e.equals("emini") || OracleOptions.ENGINES.contains(e),
                    "--engines: unknown engine " + e + " (emini, pymunk, box2d)");
        }
        SweepGrid grid = Options.grid(spec, rates, iterations);
        ScenarioLoader loader = library.loader();
        List<Sweep.SceneFile> scenes = new ArrayList<>();
        for (Path f : library.files(spec, paths)) {
            scenes.add(Sweep.read(loader, f));
        }
        List<SweepBackend> backends = new ArrayList<>();
        List<OracleBackend> oracles = new ArrayList<>();
        for (String e : engines) {
            switch (e) {
                case "emini" -> backends.add(new EngineBackend(loader));
                default -> {
                    OracleBackend o = oracle.backend(library, reports.resolve(e.equals("pymunk") ? "oracle-serve.log"
                            : "oracle-serve-" + e + ".log"), e);
                    oracles.add(o);
                    backends.add(o);
                }
            }
        }
        try {
            return sweep(grid, loader, scenes, backends, oracles, k, n);
        } finally {
            for (OracleBackend o : oracles) {
                o.close();
            }
        }
    }

    private int sweep(SweepGrid grid, ScenarioLoader loader, List<Sweep.SceneFile> scenes, List<SweepBackend> backends,
                      List<OracleBackend> oracles, int k, int n) throws Exception {
        for (SweepBackend b : backends) {
            if (b.unavailable() != null) {
                System.err.println("sweep: " + b.name() + " skipped: " + b.unavailable());
            }
        }
        for (OracleBackend o : oracles) {
            if (o.unavailable() == null) {
                System.out.println("sweep: oracle " + o.versions() + " (one process for the whole sweep)");
            }
        }
        PointStore store = new PointStore(results != null ? results : reports.resolve("points.jsonl"));
        Sweep sweep = new Sweep(loader, grid, repeats);
        List<Sweep.Task> tasks = sweep.tasks(scenes, backends, k, n, store.completed());
        System.out.printf(Locale.ROOT, "sweep: %d scenes, %d rates x %d iteration counts, shard %d/%d: %d points to run%n",
                scenes.size(), grid.rates().size(), grid.iterations().size(), k, n, tasks.size());
        boolean bar = progress != null ? progress : System.console() != null;
        long t0 = System.nanoTime();
        try (ProgressBar pb = bar ? new ProgressBarBuilder().setTaskName("points").setInitialMax(tasks.size())
                .setConsumer(new ConsoleProgressBarConsumer(System.err)).setUpdateIntervalMillis(250).build() : null) {
            sweep.run(tasks, p -> {
                try {
                    store.append(p);
                } catch (java.io.IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
                if (pb != null) {
                    pb.step();
                    pb.setExtraMessage(p.scene());
                }
            });
        }
        System.out.printf(Locale.ROOT, "sweep: done in %.1f s; results in %s%n", (System.nanoTime() - t0) / 1e9, store.file());
        if (!noPlots) {
            List<SweepPoint> all = PointStore.loadAll(store.file().toAbsolutePath().getParent());
            int plots = WorkPrecisionPlots.write(all, reports.resolve("plots"), plotCost.equals("cpu"));
            System.out.println("sweep: " + plots + " plots in " + reports.resolve("plots"));
        }
        return 0;
    }
}
