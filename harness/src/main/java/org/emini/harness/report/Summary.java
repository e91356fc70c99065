package org.emini.harness.report;

import java.util.List;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.Status;

/**
 * The counts of a run.
 *
 * @param total scenes
 * @param pass scenes that passed
 * @param known scenes that failed only where marked
 * @param fail regressions
 * @param unsupported scenes using elements the engine lacks
 * @param error invalid scenes and runs that threw
 * @param stale known-failure marks that now pass
 * @param seconds wall time of the whole run
 */
public record Summary(int total, int pass, int known, int fail, int unsupported, int error, int stale, double seconds) {

    /** Counts results. */
    public static Summary of(List<SceneResult> results, double seconds) {
        int[] n = new int[Status.values().length];
        int stale = 0;
        for (SceneResult r : results) {
            n[r.status().ordinal()]++;
            stale += r.staleKnownFailures().size();
        }
        return new Summary(results.size(), n[Status.PASS.ordinal()], n[Status.KNOWN_FAILURE.ordinal()],
                n[Status.FAIL.ordinal()], n[Status.UNSUPPORTED.ordinal()], n[Status.ERROR.ordinal()], stale, seconds);
    }

    /** Whether the run fails (a regression or an error). */
    public boolean failed() {
        return fail > 0 || error > 0;
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT,
                "%d scenes: %d pass, %d known failures, %d failed, %d unsupported, %d errors%s (%.1f s)",
                total, pass, known, fail, unsupported, error,
                stale > 0 ? ", " + stale + " known-failure marks now pass" : "", seconds);
    }
}
