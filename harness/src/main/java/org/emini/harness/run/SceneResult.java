package org.emini.harness.run;

import java.util.List;
import org.emini.harness.expect.Verdict;
import org.emini.harness.metrics.PenetrationPair;
import org.emini.harness.scenario.KnownFailure;

/**
 * What running one scene gave.
 *
 * @param scene the scene id
 * @param file the scene file
 * @param category the library category, or null
 * @param status the verdict
 * @param message why (unsupported element, error, first regression), or ""
 * @param verdicts one per expectation, in file order
 * @param staleKnownFailures expectations marked as known failures that now pass (remove the mark)
 * @param knownFailure the scene-level mark, or null
 * @param bodies number of bodies
 * @param ticks ticks run
 * @param timestep seconds per tick
 * @param buildMillis time to build the world
 * @param runMillis time to run the ticks, including metrics
 * @param trace the sampled run, or null when nothing ran
 * @param mostAsleep the most dynamic bodies asleep at one sample, or -1 when the world did not let
 *     bodies sleep (or nothing ran)
 * @param replay what the dashboard's replay draws ({@link ReplayRecorder}), or null
 * @param penetrationPairs the pairs of bodies that overlapped deepest at the samples, deepest first (at most
 *     {@link #TOP_PAIRS}; empty when the scene did not compute penetration)
 * @param stateHash the world's exact state ({@link StateHash#world}) before the first tick and after every
 *     tick, chained ({@code h = 31 h + StateHash.world(world)}): two runs of the scene that went bit for bit
 *     the same way have the same one, and two that did not almost surely another. Null unless the run
 *     reached its last tick: for an unsupported scene, a build that failed and a run stopped by an error
 *     (a body out of range, an exception, the time limit: where that stops depends on the clock), even
 *     after some ticks, so that {@code diff --same-state} compares only runs that ended
 */
public record SceneResult(String scene, String file, String category, Status status, String message,
                          List<Verdict> verdicts, List<String> staleKnownFailures, KnownFailure knownFailure,
                          int bodies, long ticks, double timestep, double buildMillis, double runMillis, Trace trace,
                          int mostAsleep, ReplayRecorder replay, List<PenetrationPair> penetrationPairs,
                          Long stateHash) {

    /** How many of the deepest pairs a result keeps (the trace keeps them all). */
    public static final int TOP_PAIRS = 5;

    /** Microseconds of wall time per tick (NaN when nothing ran). */
    public double microsPerTick() {
        return ticks == 0 ? Double.NaN : runMillis * 1000 / ticks;
    }

    /** The same result without its trace and replay (after they are written, to free memory). */
    public SceneResult withoutTrace() {
        return new SceneResult(scene, file, category, status, message, verdicts, staleKnownFailures, knownFailure,
                bodies, ticks, timestep, buildMillis, runMillis, null, mostAsleep, null, penetrationPairs, stateHash);
    }
}
