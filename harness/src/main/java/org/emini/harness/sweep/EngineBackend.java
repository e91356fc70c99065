package org.emini.harness.sweep;

import org.emini.harness.build.UnsupportedElementException;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.Status;
import org.emini.harness.scenario.Scenario;

/**
 * Runs variants in Emini. One run through the harness's own runner, with the metrics, gives the trace
 * (runs are deterministic) and lets the JIT compile the tick; then {@code repeats} runs of the ticks
 * alone ({@link ScenarioRunner#timeTicks}: actions and {@code World.tick()}, no metrics, no samples)
 * give the cost, the best of them; a repeat of a short scene runs it n times and divides by n
 * ({@link #bestTime}). The oracle times the same loop the same way ({@link OracleBackend}).
 */
public final class EngineBackend implements SweepBackend {
    /** A timed repeat lasts at least this long (s): short scenes run several times per repeat. */
    public static final double MIN_REPEAT_SECONDS = 0.02;
    /** The most runs a repeat takes. */
    public static final int MAX_RUNS_PER_REPEAT = 1024;

    private final ScenarioLoader loader;

    /** @param loader reads the variant text */
    public EngineBackend(ScenarioLoader loader) {
        this.loader = loader;
    }

    @Override
    public String name() {
        return org.emini.harness.flavour.EngineFlavour.ENGINE;
    }

    @Override
    public String unavailable() {
        return null;
    }

    @Override
    public Measured run(String sceneId, String variantText, int repeats) {
        ScenarioLoader.Loaded l = loader.load(sceneId + " (sweep variant)", variantText, sceneId);
        if (!l.ok()) {
            return new Measured("error", "invalid variant: " + l.problems(), null, Double.NaN, Double.NaN);
        }
        Scenario s = l.scenario();
        double simulated = s.ticks() * s.world().timestep();
        SceneResult traced = ScenarioRunner.run(s, n -> { });
        if (traced.status() == Status.UNSUPPORTED) {
            return new Measured("unsupported", traced.message(), null, Double.NaN, simulated);
        }
        if (traced.trace() == null) {
            return new Measured("error", traced.message(), null, Double.NaN, simulated);
        }
        try {
            double[] best = bestTime(s, repeats);
            return new Measured("ok", "", traced.trace(), best[0], simulated, best[1]);
        } catch (UnsupportedElementException | RuntimeException e) {
            return new Measured("error", "the timed run failed where the traced run did not: " + e, null,
                    Double.NaN, simulated);
        }
    }

    /**
     * Best time of the scene's ticks over {@code repeats} repeats, each of as many runs n as make it last
     * {@link #MIN_REPEAT_SECONDS} of wall time (n doubles from 1; the runs that find n are warm-up, the
     * last of them is the first repeat), divided by n: timeit's autorange, which the oracle uses too.
     *
     * @return {best wall seconds per run, best CPU seconds per run}, NaN without repeats
     */
    static double[] bestTime(Scenario s, int repeats) throws UnsupportedElementException {
        if (repeats <= 0) {
            return new double[] {Double.NaN, Double.NaN};
        }
        int n = 1;
        double[] total;
        while (true) {
            total = repeat(s, n);
            if (total[0] >= MIN_REPEAT_SECONDS || n >= MAX_RUNS_PER_REPEAT) {
                break;
            }
            n *= 2;
        }
        double wall = total[0] / n;
        double cpu = total[1] / n;
        for (int r = 1; r < repeats; r++) {
            total = repeat(s, n);
            wall = Math.min(wall, total[0] / n);
            cpu = Math.min(cpu, total[1] / n);
        }
        return new double[] {wall, cpu};
    }

    private static double[] repeat(Scenario s, int n) throws UnsupportedElementException {
        double wall = 0;
        double cpu = 0;
        for (int i = 0; i < n; i++) {
            ScenarioRunner.TickTime t = ScenarioRunner.timeTicks(s);
            wall += t.wallSeconds();
            cpu += t.cpuSeconds();
        }
        return new double[] {wall, cpu};
    }
}
