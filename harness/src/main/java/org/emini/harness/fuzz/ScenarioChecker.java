package org.emini.harness.fuzz;

import java.util.List;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.build.UnsupportedElementException;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.load.Problem;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.metrics.Metric;
import org.emini.harness.metrics.Metrics;
import org.emini.harness.run.Schedule;
import org.emini.harness.scenario.Scenario;

/**
 * A scene file as {@code validate} and {@code run} take it: loaded (parse, schema, reader, the
 * validation build), then built again with its metrics and ticked a few times with its actions. A
 * refusal must be located (file:line:column); a scene validate accepts must build, tick and sample
 * without an exception or a non-finite value.
 */
final class ScenarioChecker implements Checker {
    private final ScenarioLoader loader;
    private final int ticks;

    ScenarioChecker(ScenarioLoader loader, int ticks) {
        this.loader = loader;
        this.ticks = ticks;
    }

    @Override
    public Verdict check(byte[] input) {
        ScenarioLoader.Loaded loaded;
        try {
            loaded = loader.load("mutant.yaml", input, "mutant");
        } catch (RuntimeException | Error e) {
            return Verdict.thrown(Outcome.CRASH, "load", e);
        }
        if (!loaded.ok()) {
            return refusal(loaded.problems());
        }
        return run(loaded.scenario(), ticks);
    }

    /** Clean when every problem names a line (or, for a world file, a $.path below the root). */
    static Verdict refusal(List<Problem> problems) {
        for (Problem p : problems) {
            if (p.message().startsWith(ScenarioLoader.INTERNAL_ERROR)) {
                return new Verdict(Outcome.UNLOCATED, Verdict.HARNESS, "load", p.toString());
            }
            if (p.line() < 1) {
                return new Verdict(Outcome.UNLOCATED, Verdict.HARNESS, "load", p.toString());
            }
        }
        return Verdict.clean("load", problems.get(0).toString());
    }

    /** Builds an accepted scene as the runner does and ticks it; null-free verdict. */
    static Verdict run(Scenario scenario, int ticks) {
        BuiltWorld built;
        List<Metric> metrics;
        try {
            built = WorldBuilder.build(scenario);
            metrics = Metrics.create(scenario.run().record().metrics(), built);
        } catch (UnsupportedElementException e) {
            return Verdict.accepted("unsupported");
        } catch (RuntimeException | Error e) {
            // validate built this world: failing now is the harness contradicting itself.
            return Verdict.thrown(Outcome.CRASH, "build", e);
        }
        Schedule schedule = new Schedule(built, scenario.actions(), scenario.world().timestep());
        long n = Math.min(ticks, scenario.ticks());
        Verdict bad = WorldState.tick(built.world(), (int) n, schedule::beforeTick,
                () -> metrics.forEach(Metric::afterTick), Verdict.ENGINE, true);
        if (bad != null) {
            return bad;
        }
        return sample(metrics);
    }

    /** The metrics after the ticks: a harness metric must not compute NaN from a finite world. */
    private static Verdict sample(List<Metric> metrics) {
        for (Metric m : metrics) {
            double[] row = new double[m.channels().size()];
            try {
                m.sample(row, 0);
            } catch (RuntimeException | Error e) {
                return Verdict.thrown(Outcome.CRASH, "metrics", e);
            }
            for (int i = 0; i < row.length; i++) {
                if (!Double.isFinite(row[i])) {
                    return new Verdict(Outcome.SILENT_NAN, Verdict.HARNESS, "metrics", m.channels().get(i) + " = " + row[i]);
                }
            }
        }
        return Verdict.accepted("tick");
    }
}
