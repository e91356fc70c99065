package org.emini.harness.fuzz.world;

/**
 * Dynamic iterations agree with fixed iterations: the same separated world (no dynamic body ever
 * meets another, so the motion is not chaotic) run with a fixed iteration count and with the same
 * count as the dynamic maximum; every body's position must stay within
 * {@link #TOLERANCE} px + {@link #RELATIVE} of how far the bodies move.
 *
 * <p>Why: dynamic iterations stop solving once a relax pass changes no velocity by more than
 * SolverSettings.convergenceTolerance (0.02 px/s), then keep integrating with the converged
 * impulses; the velocity difference that leaves is of that order per tick, a few hundredths of a px
 * over a three-second run. Landing and tipping boxes amplify small differences, so the bound allows 1
 * px plus 2% of the motion; a landing body launched at (N−1)× its impact speed misses it by tens to
 * hundreds of px.
 */
final class IterationModeRelation implements Relation {
    /** Absolute tolerance (px). */
    static final double TOLERANCE = 1.0;
    /** Relative tolerance (fraction of the largest distance moved). */
    static final double RELATIVE = 0.02;

    @Override
    public ViolationKind kind() {
        return ViolationKind.ITERATION_MODE;
    }

    @Override
    public Profile profile() {
        return Profile.SEPARATED;
    }

    @Override
    public Violation check(Recipe r) {
        Recipe fixed = r.copy();
        fixed.dynamicIterations = false;
        Recipe dynamic = r.copy();
        dynamic.dynamicIterations = true;
        Trajectory a = Trajectory.run(fixed, r.ticks);
        Trajectory b = Trajectory.run(dynamic, r.ticks);
        Deviation d = Deviation.of(a, b, 1, 0, 0);
        double bound = TOLERANCE + RELATIVE * d.path();
        if (d.distance() > bound || b.error != null && a.error == null) {
            return new Violation(kind(), d.tick(), "with dynamic iterations " + d + ", bound " + String.format("%.4g", bound)
                    + " px" + (b.error != null ? "; the dynamic run threw " + b.error : ""));
        }
        return null;
    }
}
