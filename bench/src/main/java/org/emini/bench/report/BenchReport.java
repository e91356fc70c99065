package org.emini.bench.report;

import java.util.List;
import java.util.Map;
import org.emini.bench.run.Measurement;

/**
 * Everything one {@code ./emini bench} run found, as written to {@code bench.json}.
 *
 * @param format always {@code emini-bench}
 * @param version format version, 1
 * @param generated when (ISO-8601, UTC)
 * @param mode {@code quick} or {@code full}
 * @param jmh the JMH settings used
 * @param machine CPU, cores, memory, OS, JVM, load average at the start
 * @param loadAverageEnd the 1-minute load average at the end
 * @param seconds how long the run took
 * @param scenes the comparison table, one entry per scene
 * @param scaling the rain series, every engine at every count
 * @param external the out-of-process engines' status and message by engine id (pymunk, box2d-v3, rapier)
 * @param resumed true when the run ({@code --resume}) kept figures an earlier run measured, whose time
 *     {@code seconds} does not count
 */
public record BenchReport(String format, int version, String generated, String mode, Map<String, Object> jmh,
                          Map<String, Object> machine, double loadAverageEnd, double seconds, List<SceneEntry> scenes,
                          List<Measurement> scaling, Map<String, Map<String, Object>> external,
                          boolean resumed) {

    /** The run's time as the page and the tables print it, saying when it kept earlier figures. */
    public String runTime() {
        return String.format(java.util.Locale.ROOT, "%.0f s", seconds) + (resumed ? ", resumed with figures kept from an earlier run" : "");
    }

    /**
     * One scene of the table.
     *
     * @param id scene id
     * @param title what it is
     * @param status {@code ran} or {@code pending}
     * @param message what a pending scene waits for
     * @param results one per engine
     */
    public record SceneEntry(String id, String title, String status, String message, List<Measurement> results) {
    }
}
