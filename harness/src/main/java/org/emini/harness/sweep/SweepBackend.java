package org.emini.harness.sweep;

import org.emini.harness.run.Trace;

/**
 * Something a sweep runs scene variants in: the engine, or the pymunk oracle (issue 6).
 */
public interface SweepBackend {
    /** The engine's name in results and plots ({@code emini}, {@code pymunk}). */
    String name();

    /** Null when the backend can run; otherwise why not (shown in the report, no points are run). */
    String unavailable();

    /**
     * Runs one variant {@code repeats} times.
     *
     * @param sceneId the scene id
     * @param variantText the variant scene (JSON text, see {@link SceneVariant})
     * @param repeats runs to take the best wall time of
     * @return the last run's trace (runs are deterministic) and the best wall time
     */
    Measured run(String sceneId, String variantText, int repeats);

    /**
     * What running a variant gave.
     *
     * @param status {@code ok}, {@code unsupported} or {@code error} (instability is judged from the trace)
     * @param message why, or ""
     * @param trace the samples, or null
     * @param bestSeconds best wall time of the ticks over the repeats (s)
     * @param simulatedSeconds simulated time (s)
     */
    record Measured(String status, String message, Trace trace, double bestSeconds, double simulatedSeconds) {
    }
}
