package org.emini.harness.scenario;

/**
 * One channel of a stored trace that an expectation subtracts from the run's ({@code minus: {trace: FILE}}):
 * a run compared with a reference run, sample by sample.
 *
 * @param file the trace file as the scene writes it (relative to the scene's folder)
 * @param channel the channel read from it
 * @param timestep the reference's seconds per tick
 * @param ticks the tick of each of its samples
 * @param values the channel's value at each sample (NaN where the trace holds null)
 */
public record ReferenceTrace(String file, String channel, double timestep, long[] ticks, double[] values) {

    /** The same reference with its values multiplied by {@code f} (a scaled run, {@code run --scale}). */
    public ReferenceTrace times(double f) {
        double[] v = values.clone();
        for (int i = 0; i < v.length; i++) {
            v[i] *= f;
        }
        return new ReferenceTrace(file, channel, timestep, ticks, v);
    }

    /**
     * Why a run sampled at these ticks cannot be compared with this reference sample by sample, or null.
     *
     * @param runTimestep the run's seconds per tick
     * @param runTicks the run's sample ticks
     */
    public String mismatch(double runTimestep, long[] runTicks) {
        if (Math.abs(runTimestep - timestep) > 1e-9 * timestep) {
            return "the reference trace " + file + " has a timestep of " + timestep + " s, this run " + runTimestep + " s";
        }
        if (runTicks.length != ticks.length) {
            return "the reference trace " + file + " has " + ticks.length + " samples (last tick " + ticks[ticks.length - 1]
                    + "), this run " + runTicks.length + " (last tick " + runTicks[runTicks.length - 1]
                    + "): run.duration and run.record.every must be the reference's";
        }
        for (int i = 0; i < ticks.length; i++) {
            if (ticks[i] != runTicks[i]) {
                return "the reference trace " + file + " samples tick " + ticks[i] + " where this run samples tick "
                        + runTicks[i] + " (sample " + i + "): run.record.every must be the reference's";
            }
        }
        return null;
    }
}
