package org.emini.harness.fuzz.world;

/**
 * Halving the timestep brings the result closer to finer runs. A smooth world (no contacts, no
 * damping: projectiles, pendulums, springs, motors, constant forces) runs for the same simulated time
 * at 20, 40, 80 and 160 ticks per second and, as the reference, at 640, with the same iteration count
 * (motor caps kept as forces, not impulses per tick); its error at a rate is the largest distance of a
 * dynamic body from the reference over samples every 0.05 s. Each halving must lower the error, until
 * it is below the round-off floor: {@link #FLOOR} px plus half a float step at the largest coordinate
 * reached for every substep of the run and of the reference.
 *
 * <p>Why: the solver is first order in the substep for smooth motion (README: the error of a
 * projectile or pendulum falls in proportion to the timestep), so each halving roughly halves the
 * distance to a run 16 times finer; the floor is where float round-off takes over from the
 * integration error: each substep rounds every position to its float step (3·10⁻⁵ px at 500 px), and a
 * body moving steadily rounds the same way every time, so the roundings add up (measured: a projectile
 * whose error fell 0.51, 0.28, 0.18 px stayed at 0.20 px at 160 ticks/s, against a reference of 12,800
 * substeps, up to 0.39 px of round-off there).
 */
final class ConvergenceRelation implements Relation {
    /** Round-off allowed besides the per-substep part (px). */
    static final double FLOOR = 0.05;
    private static final int[] RATES = {20, 40, 80, 160};
    private static final int REFERENCE = 640;

    @Override
    public ViolationKind kind() {
        return ViolationKind.CONVERGENCE;
    }

    @Override
    public Profile profile() {
        return Profile.SMOOTH;
    }

    @Override
    public Violation check(Recipe r) {
        double seconds = r.ticks / (double) r.ticksPerSecond;
        Trajectory reference = Trajectory.run(at(r, REFERENCE), (int) Math.round(seconds * REFERENCE));
        double[] errors = new double[RATES.length];
        double[] floors = new double[RATES.length];
        for (int i = 0; i < RATES.length; i++) {
            Trajectory t = Trajectory.run(at(r, RATES[i]), (int) Math.round(seconds * RATES[i]));
            if (t.error != null || reference.error != null) {
                return t.error == null && reference.error == null ? null : new Violation(kind(), -1,
                        "a run threw: " + (t.error != null ? t.error : reference.error));
            }
            errors[i] = error(t, RATES[i], reference, seconds);
            floors[i] = FLOOR + (t.ticks + reference.ticks) * r.iterations * 0.5 * Math.ulp((float) reach(reference));
        }
        for (int i = 1; i < RATES.length; i++) {
            if (errors[i - 1] > floors[i - 1] && errors[i] >= errors[i - 1]) {
                return new Violation(kind(), -1, String.format(
                        "the error against %d ticks/s does not fall from %d to %d ticks/s: %s px at 20, 40, 80, 160 ticks/s "
                                + "(round-off floor %.3g px)", REFERENCE, RATES[i - 1], RATES[i], format(errors), floors[i - 1]));
            }
        }
        return null;
    }

    /** The recipe at another tick rate, its motors' caps scaled so that the force stays the same. */
    static Recipe at(Recipe r, int rate) {
        Recipe c = r.copy();
        c.ticksPerSecond = rate;
        for (MotorRecipe m : c.motors) {
            m.maxImpulse = m.maxImpulse * r.ticksPerSecond / rate;
        }
        return c;
    }

    private static double error(Trajectory t, int rate, Trajectory reference, double seconds) {
        double worst = 0;
        int samples = (int) Math.round(seconds * 20);
        for (int s = 0; s <= samples; s++) {
            int k = s * rate / 20;
            int kr = s * REFERENCE / 20;
            for (int i = 0; i < t.bodies(); i++) {
                if (t.recipe.bodies.get(i).dynamic) {
                    worst = Math.max(worst, Math.hypot(t.get(k, i, 0) - reference.get(kr, i, 0), t.get(k, i, 1) - reference.get(kr, i, 1)));
                }
            }
        }
        return worst;
    }

    /** The largest coordinate a dynamic body reaches (px). */
    private static double reach(Trajectory t) {
        double most = 0;
        for (int k = 0; k <= t.ticks; k++) {
            for (int i = 0; i < t.bodies(); i++) {
                most = Math.max(most, Math.max(Math.abs(t.get(k, i, 0)), Math.abs(t.get(k, i, 1))));
            }
        }
        return most;
    }

    private static String format(double[] errors) {
        StringBuilder b = new StringBuilder();
        for (double e : errors) {
            b.append(b.length() == 0 ? "" : ", ").append(String.format("%.4g", e));
        }
        return b.toString();
    }
}
