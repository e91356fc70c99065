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
 * @param seconds how long the run took (a resumed run: with the runs whose figures it kept)
 * @param scenes the comparison table, one entry per scene
 * @param scaling the rain series, every engine at every count
 * @param pymunk the Python engine's status and figures
 */
public record BenchReport(String format, int version, String generated, String mode, Map<String, Object> jmh,
                          Map<String, Object> machine, double loadAverageEnd, double seconds, List<SceneEntry> scenes,
                          List<Measurement> scaling, Map<String, Object> pymunk) {

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
