package org.emini.harness.sweep;

/**
 * One measured point of a sweep: a scene run by one engine at one timestep and iteration count.
 *
 * @param scene the scene id
 * @param engine who ran it ({@code emini}, {@code pymunk})
 * @param rate ticks per second (timestep = 1 / rate)
 * @param iterations solver iterations
 * @param status {@code ok}, {@code unstable} (NaN or infinite state), {@code unsupported}, {@code error}
 * @param message why, for a status other than ok
 * @param reference {@code closedForm:MODEL} or {@code self:RATE/ITERATIONS} (the same engine's tightest setting)
 * @param finalError mean distance of the compared bodies from the reference at the last sample (px)
 * @param maxError the largest such mean distance over the samples: the error over the whole run (px)
 * @param rmsError its root mean square over the samples (px)
 * @param costSeconds best wall time per simulated second over the repeats (s/s)
 * @param repeats repeats the cost is the best of
 * @param energyDrift max |E(t) − E(0)| over the run divided by the largest kinetic energy (NaN when the
 *     scene does not conserve energy)
 * @param momentumDrift max |p(t) − p(0)| over the largest |p| (NaN when the scene does not conserve momentum)
 * @param motion the reference's largest distance of a compared body from its start (px): the scale
 *     {@link #relativeError()} divides by (NaN when unknown)
 * @param cpuCostSeconds the same as {@code costSeconds} in CPU time of the ticking thread: unlike wall
 *     time, not inflated by other processes on a busy machine (NaN when unknown)
 */
public record SweepPoint(String scene, String engine, int rate, int iterations, String status, String message,
                         String reference, double finalError, double maxError, double rmsError, double costSeconds,
                         int repeats, double energyDrift, double momentumDrift, double motion,
                         double cpuCostSeconds) {

    /** The whole-run error over the motion: 0.01 is an error of 1% of how far the bodies move (NaN when unknown). */
    public double relativeError() {
        return motion > 0 ? maxError / motion : Double.NaN;
    }

    /** The key a results file is resumed by. */
    public String key() {
        return key(scene, engine, rate, iterations);
    }

    /** The key of a point. */
    public static String key(String scene, String engine, int rate, int iterations) {
        return scene + "|" + engine + "|" + rate + "|" + iterations;
    }
}
