package org.emini.harness.sweep;

import org.emini.harness.run.Trace;

/**
 * Something a sweep or stability map runs scene variants in: the engine ({@link EngineBackend}) or the
 * pymunk oracle ({@link OracleBackend}). Both time the same thing: the ticks alone, after a run with the
 * metrics that gives the trace.
 */
public interface SweepBackend {
    /** The engine's name in results and plots ({@code emini}, {@code pymunk}). */
    String name();

    /** Null when the backend can run; otherwise why not (shown in the report, no points are run). */
    String unavailable();

    /**
     * Runs one variant once with its metrics (the trace, and the warm-up), then {@code repeats} times
     * with its ticks alone, timed.
     *
     * @param sceneId the scene id
     * @param variantText the variant scene (JSON text, see {@link SceneVariant})
     * @param repeats timed runs to take the best wall time of; 0 for the trace only (the cost is NaN)
     * @return the trace and the best wall time
     */
    Measured run(String sceneId, String variantText, int repeats);

    /**
     * What running a variant gave.
     *
     * @param status {@code ok}, {@code unsupported} or {@code error} (instability is judged from the trace)
     * @param message why, or "" (for {@code ok}: what the backend runs differently, or "")
     * @param trace the samples, or null
     * @param bestSeconds best wall time of the ticks alone over the repeats (s), NaN without repeats
     * @param simulatedSeconds simulated time (s)
     * @param bestCpuSeconds best CPU time of the ticking thread over the repeats (s), NaN when unknown
     */
    record Measured(String status, String message, Trace trace, double bestSeconds, double simulatedSeconds,
                    double bestCpuSeconds) {
        /** Without a CPU time. */
        public Measured(String status, String message, Trace trace, double bestSeconds, double simulatedSeconds) {
            this(status, message, trace, bestSeconds, simulatedSeconds, Double.NaN);
        }
    }
}
