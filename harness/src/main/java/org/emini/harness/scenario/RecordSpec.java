package org.emini.harness.scenario;

import java.util.List;

/**
 * What the run samples and how often.
 *
 * @param every sampling interval in seconds (NaN: every tick)
 * @param metrics the metrics to compute, including those expectations need
 * @param bodies which bodies' state is sampled: "all", "dynamic", "none" or null with {@code bodyNames}
 * @param bodyNames named bodies to sample, when {@code bodies} is null
 * @param trace whether a trace file is written
 */
public record RecordSpec(double every, List<MetricSpec> metrics, String bodies, List<String> bodyNames,
                         boolean trace) {

    /** Ticks between samples: the record interval rounded to whole ticks (at least one). */
    public long samplingTicks(double timestep) {
        return Double.isNaN(every) ? 1 : Math.max(1, Math.round(every / timestep));
    }
}
