package org.emini.harness.metrics;

import java.util.List;

/**
 * A recorded quantity of the run. Each metric fills a fixed set of channels (scalars) at every sample;
 * definitions are in scenarios/README.md, Metrics, and nowhere else.
 */
public interface Metric {
    /** The channels this metric fills, in order. */
    List<String> channels();

    /**
     * Called after every tick, for monitors that must not miss an event between samples (tunnelling,
     * stability). Most metrics do nothing here, so they cost nothing between samples.
     */
    default void afterTick() {
    }

    /**
     * Writes the current values.
     *
     * @param out the sample row
     * @param offset where this metric's first channel goes
     */
    void sample(double[] out, int offset);
}
