package org.emini.harness.fuzz.world;

import java.util.function.Consumer;
import org.emini.dynamics.Body;
import org.emini.harness.run.StateHash;

/**
 * The states of a run: after each tick (and before the first), every recipe body's x, y, angle, vx,
 * vy, omega, and a hash of the rest (the recipe's constraints' forces and its emitters' particles).
 * A tick that throws ends the run; {@link #error} says what it threw.
 */
final class Trajectory {
    static final int FIELDS = 6;
    private static final String[] NAMES = {"x", "y", "angle", "vx", "vy", "omega"};

    final Recipe recipe;
    final float[][] states;
    final long[] rest;
    final int ticks;
    final String error;

    private Trajectory(Recipe recipe, float[][] states, long[] rest, int ticks, String error) {
        this.recipe = recipe;
        this.states = states;
        this.rest = rest;
        this.ticks = ticks;
        this.error = error;
    }

    static Trajectory run(Recipe r, int ticks) {
        return run(r, ticks, w -> { });
    }

    /** Builds the recipe, lets {@code change} add to the world, and runs it. */
    static Trajectory run(Recipe r, int ticks, Consumer<FuzzWorld> change) {
        FuzzWorld w = RecipeBuilder.build(r);
        change.accept(w);
        return run(w, ticks);
    }

    /** Runs a built world. */
    static Trajectory run(FuzzWorld w, int ticks) {
        Recipe r = w.recipe();
        float[][] states = new float[ticks + 1][];
        long[] rest = new long[ticks + 1];
        states[0] = state(w);
        rest[0] = rest(w);
        int k = 0;
        String error = null;
        try {
            for (; k < ticks; k++) {
                w.tick();
                states[k + 1] = state(w);
                rest[k + 1] = rest(w);
            }
        } catch (RuntimeException e) {
            error = TickFailure.describe(e);
        }
        return new Trajectory(r, states, rest, k, error);
    }

    private static float[] state(FuzzWorld w) {
        float[] s = new float[FIELDS * w.bodies().length];
        for (int i = 0; i < w.bodies().length; i++) {
            Body b = w.bodies()[i];
            s[FIELDS * i] = b.getX();
            s[FIELDS * i + 1] = b.getY();
            s[FIELDS * i + 2] = b.getAngle();
            s[FIELDS * i + 3] = b.getVelocityX();
            s[FIELDS * i + 4] = b.getVelocityY();
            s[FIELDS * i + 5] = b.getAngularVelocity();
        }
        return s;
    }

    private static long rest(FuzzWorld w) {
        long h = 17;
        for (Object c : w.constraints().values()) {
            h = 31 * h + Float.floatToIntBits(((org.emini.dynamics.Constraint) c).getForce());
        }
        for (int e = 0; e < w.recipe().emitters.size(); e++) {
            h = 31 * h + StateHash.particles(w.emitters().get(e));
        }
        return h;
    }

    /** Body count. */
    int bodies() {
        return states[0].length / FIELDS;
    }

    /** Field f of body i after tick k (k = 0: before the first tick). */
    float get(int k, int i, int f) {
        return states[k][FIELDS * i + f];
    }

    /**
     * The first difference in bits from another run of the same bodies over their common ticks, or
     * null when there is none (and both threw alike, or neither did).
     */
    String firstDifference(Trajectory other, int ticks) {
        int n = Math.min(ticks, Math.min(this.ticks, other.ticks));
        for (int k = 0; k <= n; k++) {
            for (int j = 0; j < states[k].length; j++) {
                if (Float.floatToIntBits(states[k][j]) != Float.floatToIntBits(other.states[k][j])) {
                    return String.format("after tick %d body %d's %s is %s instead of %s", k - 1,
                            recipe.bodies.get(j / FIELDS).id, NAMES[j % FIELDS], other.states[k][j], states[k][j]);
                }
            }
            if (rest[k] != other.rest[k]) {
                return "after tick " + (k - 1) + " the constraint forces or particles differ";
            }
        }
        if (n < ticks && (this.ticks != other.ticks || error == null != (other.error == null))) {
            return "one run threw after " + other.ticks + " ticks (" + other.error + "), the other after " + this.ticks
                    + " (" + error + ")";
        }
        return null;
    }
}
