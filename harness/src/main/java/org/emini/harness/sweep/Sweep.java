package org.emini.harness.sweep;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import org.emini.harness.closedform.ClosedForm;
import org.emini.harness.closedform.ClosedForms;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.run.Trace;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Channels;
import org.emini.harness.scenario.Scenario;

/**
 * A work-precision sweep: every scene run over a grid of timesteps and iteration counts by each
 * backend; each point's error against the scene's closed form where it has one, else against the same
 * backend at the grid's tightest setting (self-consistency); its cost as the best wall time per
 * simulated second over repeats; and the drift of conserved quantities where the scene conserves them.
 */
public final class Sweep {
    /** One scene to sweep. */
    public record SceneFile(String id, String text) {
    }

    /** One point still to run. */
    public record Task(SceneFile scene, SweepBackend backend, int rate, int iterations) {
        String key() {
            return SweepPoint.key(scene.id(), backend.name(), rate, iterations);
        }
    }

    private final ScenarioLoader loader;
    private final SweepGrid grid;
    private final int repeats;
    private final Map<String, Trace> references = new HashMap<>();
    private final Map<String, Scenario> scenarios = new HashMap<>();
    private final Map<String, ClosedForm> closedForms = new HashMap<>();

    /**
     * @param loader reads variants (for the closed forms and conservation flags)
     * @param grid timesteps and iterations
     * @param repeats runs per point; the cost is the best
     */
    public Sweep(ScenarioLoader loader, SweepGrid grid, int repeats) {
        this.loader = loader;
        this.grid = grid;
        this.repeats = repeats;
    }

    /**
     * The points of shard {@code k} of {@code n} (1-based) not yet in {@code done}, in a fixed order:
     * point i of the whole sweep belongs to shard (i mod n) + 1. Points of a backend that is
     * {@linkplain SweepBackend#unavailable() unavailable} are left out (a later run picks them up).
     */
    public List<Task> tasks(List<SceneFile> scenes, List<SweepBackend> backends, int k, int n, Set<String> done) {
        List<Task> out = new ArrayList<>();
        int i = 0;
        for (SceneFile s : scenes) {
            for (SweepBackend b : backends) {
                if (b.unavailable() != null) {
                    continue;
                }
                for (int rate : grid.rates()) {
                    for (int it : grid.iterations()) {
                        Task t = new Task(s, b, rate, it);
                        if (i++ % n == k - 1 && !done.contains(t.key())) {
                            out.add(t);
                        }
                    }
                }
            }
        }
        return out;
    }

    /** Runs the tasks in order, handing each finished point to {@code sink}. */
    public void run(List<Task> tasks, Consumer<SweepPoint> sink) {
        for (Task t : tasks) {
            sink.accept(measure(t));
        }
    }

    /** Runs one point. */
    public SweepPoint measure(Task t) {
        String id = t.scene().id();
        String variant = SceneVariant.rewrite(t.scene().text(), id, 1.0 / t.rate(), t.iterations(), grid.every());
        SweepBackend.Measured m = t.backend().run(id, variant, repeats);
        if (!m.status().equals("ok")) {
            return new SweepPoint(id, t.backend().name(), t.rate(), t.iterations(), m.status(), m.message(), "",
                    Double.NaN, Double.NaN, Double.NaN, Double.NaN, repeats, Double.NaN, Double.NaN, Double.NaN,
                    Double.NaN);
        }
        Scenario s = scenario(t.scene());
        List<String> bodies = comparedBodies(s, m.trace());
        double cost = m.bestSeconds() / m.simulatedSeconds();
        double cpuCost = m.bestCpuSeconds() / m.simulatedSeconds();
        ClosedForm cf = closedForm(t.scene());
        double[] errors;
        String reference;
        double motion;
        if (cf != null && Accuracy.predictsAny(m.trace(), bodies, cf)) {
            errors = Accuracy.againstClosedForm(m.trace(), bodies, cf);
            motion = Accuracy.motion(m.trace(), bodies, cf);
            reference = "closedForm:" + s.closedForm().node().get("model").asText();
        } else {
            Trace ref = reference(t, m.trace());
            reference = "self:" + grid.tightestRate() + "/" + grid.tightestIterations();
            if (ref == null) {
                return new SweepPoint(id, t.backend().name(), t.rate(), t.iterations(), "error",
                        "the reference setting did not run", reference, Double.NaN, Double.NaN, Double.NaN, cost,
                        repeats, Double.NaN, Double.NaN, Double.NaN, cpuCost);
            }
            errors = Accuracy.againstTrace(m.trace(), bodies, ref);
            motion = Accuracy.motion(ref, bodies, null);
        }
        double[] e = Accuracy.reduce(errors);
        boolean blewUp = !finite(m.trace(), bodies);
        double energy = Double.NaN;
        if (conservesEnergy(s) && m.trace().has("energy.total")) {
            energy = Accuracy.drift(m.trace().column("energy.total"), Accuracy.maxAbs(m.trace().column("energy.kinetic")));
        }
        double momentum = Double.NaN;
        if (conservesMomentum(s) && m.trace().has("momentum.x")) {
            double[] px = m.trace().column("momentum.x");
            double[] py = m.trace().column("momentum.y");
            double scale = Math.max(Accuracy.maxAbs(px), Accuracy.maxAbs(py));
            momentum = Math.max(Accuracy.drift(px, scale), Accuracy.drift(py, scale));
        }
        return new SweepPoint(id, t.backend().name(), t.rate(), t.iterations(), blewUp ? "unstable" : "ok",
                blewUp ? "NaN or infinite state" : m.message(), reference, e[0], e[1], e[2], cost, repeats, energy, momentum, motion, cpuCost);
    }

    private synchronized Trace reference(Task t, Trace own) {
        if (t.rate() == grid.tightestRate() && t.iterations() == grid.tightestIterations()) {
            return own;
        }
        String key = t.scene().id() + "|" + t.backend().name();
        if (!references.containsKey(key)) {
            String v = SceneVariant.rewrite(t.scene().text(), t.scene().id(), 1.0 / grid.tightestRate(),
                    grid.tightestIterations(), grid.every());
            SweepBackend.Measured m = t.backend().run(t.scene().id(), v, 0);
            references.put(key, m.status().equals("ok") ? m.trace() : null);
        }
        return references.get(key);
    }

    private synchronized Scenario scenario(SceneFile f) {
        return scenarios.computeIfAbsent(f.id(), id -> {
            String v = SceneVariant.rewrite(f.text(), id, 1.0 / grid.tightestRate(), grid.tightestIterations(), grid.every());
            ScenarioLoader.Loaded l = loader.load(id, v, id);
            if (!l.ok()) {
                throw new IllegalArgumentException("invalid sweep variant of " + id + ": " + l.problems());
            }
            return l.scenario();
        });
    }

    private synchronized ClosedForm closedForm(SceneFile f) {
        if (!closedForms.containsKey(f.id())) {
            // Null without a model: the points fall back to self-consistency.
            closedForms.put(f.id(), ClosedForms.of(scenario(f)));
        }
        return closedForms.get(f.id());
    }

    /** Dynamic bodies the trace recorded. */
    static List<String> comparedBodies(Scenario s, Trace trace) {
        List<String> out = new ArrayList<>();
        for (BodySpec b : s.bodies()) {
            if (!b.state().isStatic() && trace.has(Channels.body(b.name(), "x"))) {
                out.add(b.name());
            }
        }
        return out;
    }

    private static boolean finite(Trace trace, List<String> bodies) {
        for (String b : bodies) {
            for (double v : trace.column(Channels.body(b, "x"))) {
                if (!Double.isFinite(v)) {
                    return false;
                }
            }
            for (double v : trace.column(Channels.body(b, "y"))) {
                if (!Double.isFinite(v)) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * Whether the scene's physics conserves energy: no damping, and a closed form that does (projectile,
     * free rotation, pendulum, or a collision or bounce with elasticity 1).
     */
    static boolean conservesEnergy(Scenario s) {
        if (s.world().dampingLateral() != 0 || s.world().dampingRotational() != 0 || s.closedForm() == null) {
            return false;
        }
        JsonNode c = s.closedForm().node();
        switch (c.get("model").asText()) {
            case "projectile":
            case "freeRotation":
            case "pendulum":
                return true;
            case "collision1d":
            case "bouncingBall":
                return c.path("elasticity").asDouble(0) == 1;
            default:
                return false;
        }
    }

    /** Whether linear momentum is conserved: no gravity, no static bodies, no actions, no damping. */
    static boolean conservesMomentum(Scenario s) {
        return s.world().gravityX() == 0 && s.world().gravityY() == 0 && s.actions().isEmpty()
                && s.world().dampingLateral() == 0 && s.bodies().stream().noneMatch(b -> b.state().isStatic());
    }

    /** Reads a scene file for a sweep. */
    public static SceneFile read(ScenarioLoader loader, java.nio.file.Path file) throws IOException {
        ScenarioLoader.Loaded l = loader.load(file);
        if (!l.ok()) {
            throw new IllegalArgumentException("invalid scene " + file + ": " + l.problems());
        }
        return new SceneFile(l.scenario().name(), java.nio.file.Files.readString(file));
    }
}
