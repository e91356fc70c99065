package org.emini.harness.sweep;

import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.Status;
import org.emini.harness.scenario.Scenario;

/** Runs variants in Emini through the harness's own runner (the wall time covers ticks and metrics). */
public final class EngineBackend implements SweepBackend {
    private final ScenarioLoader loader;

    /** @param loader reads the variant text */
    public EngineBackend(ScenarioLoader loader) {
        this.loader = loader;
    }

    @Override
    public String name() {
        return "emini";
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
        double best = Double.POSITIVE_INFINITY;
        SceneResult last = null;
        if (repeats > 1) {
            ScenarioRunner.run(s, n -> { }); // untimed: lets the JIT compile the tick before the timed runs
        }
        for (int i = 0; i < Math.max(1, repeats); i++) {
            last = ScenarioRunner.run(s, n -> { });
            if (last.status() == Status.UNSUPPORTED) {
                return new Measured("unsupported", last.message(), null, Double.NaN, simulated);
            }
            if (last.trace() == null) {
                return new Measured("error", last.message(), null, Double.NaN, simulated);
            }
            best = Math.min(best, last.runMillis() / 1000);
        }
        return new Measured("ok", "", last.trace(), best, simulated);
    }
}
