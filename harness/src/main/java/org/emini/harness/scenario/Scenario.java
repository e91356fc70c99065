package org.emini.harness.scenario;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A validated scene, with defaults filled in and generators expanded into bodies.
 *
 * @param name the scene id ({@code stacking/tower-10})
 * @param file the file it was read from
 * @param description what the scene shows, or ""
 * @param category the library category, or null
 * @param world world settings
 * @param shapes named shapes
 * @param bodies every body, in creation order (written bodies first, then generators in order)
 * @param actions scheduled actions, in file order
 * @param elements elements kept as written, by top-level key (joints, springs, motors, landscape,
 *     particles) plus {@code world.simulationArea}; built by their own builders
 * @param run duration, record and expectations
 * @param closedForm the closed-form reference, or null
 * @param oracle the oracle settings ({@code reference.oracle}), or null
 * @param knownFailure a mark for the whole scene, or null
 */
public record Scenario(String name, String file, String description, String category, WorldSpec world,
                       Map<String, ShapeSpec> shapes, List<BodySpec> bodies, List<ActionSpec> actions,
                       Map<String, Section> elements, RunSpec run, Section closedForm, Section oracle,
                       KnownFailure knownFailure) {
    /** The solver key {@link #withNudge} scales (a SolverSettings name, as world.solver spells it). */
    public static final String SPECULATIVE_DISTANCE = "speculativeDistance";

    /** The body with this name, or null. */
    public BodySpec body(String bodyName) {
        for (BodySpec b : bodies) {
            if (b.name().equals(bodyName)) {
                return b;
            }
        }
        return null;
    }

    /** The same scene with other elements (none: its bodies alone). */
    public Scenario withElements(Map<String, Section> newElements) {
        return new Scenario(name, file, description, category, world, shapes, bodies, actions, newElements, run,
                closedForm, oracle, knownFailure);
    }

    /**
     * The same scene with sleeping forced on or off, keeping the tolerances it gives (the harness's
     * {@code run --sleeping}).
     */
    public Scenario withSleeping(boolean on) {
        return new Scenario(name, file, description, category, world.withSleeping(world.sleeping().switched(on)),
                shapes, bodies, actions, elements, run, closedForm, oracle, knownFailure);
    }

    /**
     * This scene nudged by {@code factor} ({@code run --nudge}): the engine's speculative distance (the
     * scene's own, or the engine's default) times {@code factor}, and the world's gravity times
     * {@code 1 + (factor - 1) / 10,000}, two parts per million at 1.02. Neither changes the physics
     * by anything a scene's bounds should notice, but together they change the round-off of nearly
     * every scene: the speculative distance alone reached only the scenes where some gap falls between
     * the two distances (14 of the library's 99), gravity every scene with gravity (73 to 75 of them).
     * A verdict that flips under a nudge was reached by the round-off's luck, not by a margin.
     *
     * @param factor finite and &gt; 0
     * @param defaultDistance the engine's default speculative distance, for a scene that sets none
     */
    public Scenario withNudge(double factor, double defaultDistance) {
        if (!(factor > 0) || Double.isInfinite(factor)) {
            throw new IllegalArgumentException("nudge factor must be finite and > 0, was " + factor);
        }
        Map<String, Double> solver = new HashMap<>(world.solver());
        solver.put(SPECULATIVE_DISTANCE, solver.getOrDefault(SPECULATIVE_DISTANCE, defaultDistance) * factor);
        double g = gravityNudge(factor);
        WorldSpec nudged = world.withSolver(solver).withGravity(world.gravityX() * g, world.gravityY() * g);
        List<ActionSpec> nudgedActions = new ArrayList<>();
        for (ActionSpec a : actions) {
            nudgedActions.add(a.kind() != ActionSpec.Kind.gravity ? a : new ActionSpec(a.at(), a.kind(), a.body(),
                    new double[] {a.vector()[0] * g, a.vector()[1] * g}, a.point(), a.value(), a.duration(), a.emitter(),
                    a.path()));
        }
        return new Scenario(name, file, description, category, nudged,
                shapes, bodies, List.copyOf(nudgedActions), elements, run, closedForm, oracle, knownFailure);
    }

    /** The factor on gravity of a nudge by {@code factor}: {@code 1 + (factor - 1) / 10,000}. */
    public static double gravityNudge(double factor) {
        return 1 + (factor - 1) / 10_000;
    }

    /** Number of ticks the run takes. */
    public long ticks() {
        return (long) Math.ceil(run.duration() / world.timestep() - 1e-9);
    }
}
