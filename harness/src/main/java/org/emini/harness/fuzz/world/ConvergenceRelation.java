package org.emini.harness.fuzz.world;

/**
 * Halving the timestep brings the result closer to finer runs. A smooth world (no contacts, no
 * damping: projectiles, pendulums, springs, motors, constant forces) runs for the same simulated time
 * at 20, 40, 80 and 160 ticks per second and, as the reference, at 640, with the same iteration count
 * (motor caps kept as forces, not impulses per tick); its error at a rate is the largest distance of a
 * dynamic body from the reference over samples every 0.05 s. Each halving must lower the error, until
 * it is below {@link #FLOOR} px.
 *
 * <p>Why: the solver is first order in the substep for smooth motion (README: the error of a
 * projectile or pendulum falls in proportion to the timestep), so each halving roughly halves the
 * distance to a run 16 times finer; the floor is where float round-off takes over from the
 * integration error: the reference makes up to 12,800 substeps in 2 s, each rounding positions of a
 * few hundred px to 1.5·10⁻⁵ px, 0.1 px if the roundings add up.
 */
final class ConvergenceRelation implements Relation {
    /** Errors below this are round-off (px). */
    static final double FLOOR = 0.1;
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
        for (int i = 0; i < RATES.length; i++) {
            Trajectory t = Trajectory.run(at(r, RATES[i]), (int) Math.round(seconds * RATES[i]));
            if (t.error != null || reference.error != null) {
                return t.error == null && reference.error == null ? null : new Violation(kind(), -1,
                        "a run threw: " + (t.error != null ? t.error : reference.error));
            }
            errors[i] = error(t, RATES[i], reference, seconds);
        }
        for (int i = 1; i < RATES.length; i++) {
            if (errors[i - 1] > FLOOR && errors[i] >= errors[i - 1]) {
                return new Violation(kind(), -1, String.format(
                        "the error against %d ticks/s does not fall from %d to %d ticks/s: %s px at 20, 40, 80, 160 ticks/s",
                        REFERENCE, RATES[i - 1], RATES[i], format(errors)));
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

    private static String format(double[] errors) {
        StringBuilder b = new StringBuilder();
        for (double e : errors) {
            b.append(b.length() == 0 ? "" : ", ").append(String.format("%.4g", e));
        }
        return b.toString();
    }
}
