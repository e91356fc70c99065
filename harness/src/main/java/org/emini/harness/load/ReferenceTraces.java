package org.emini.harness.load;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.emini.harness.oracle.TraceReader;
import org.emini.harness.run.Trace;
import org.emini.harness.scenario.ReferenceTrace;
import org.emini.harness.scenario.Scenario;

/**
 * Reads the stored traces expectations compare with ({@code minus: {trace: FILE}}): a trace file of the
 * format harness/README.md describes, written by {@code harness run} or by an oracle.
 */
final class ReferenceTraces {
    /** The largest reference trace read (a trace is larger than a scene; this still bounds the memory). */
    static final long MAX_BYTES = 64L << 20;

    private ReferenceTraces() {
    }

    /**
     * A reference channel, or why there is none.
     *
     * @param trace the channel read, or null
     * @param problem what is wrong, naming the file (and the channel), or null
     * @param problemAtChannel whether the problem lies in the channel asked for rather than in the file
     */
    record Found(ReferenceTrace trace, String problem, boolean problemAtChannel) {
    }

    /**
     * Reads channel {@code channel} of the trace file {@code written}, relative to the scene file's folder.
     *
     * @param sceneFile the scene file (as shown: relative to the working folder, or absolute)
     */
    static Found read(Path sceneFile, String written, String channel) {
        Path file;
        try {
            file = sceneFile.toAbsolutePath().getParent().resolve(written).normalize();
        } catch (java.nio.file.InvalidPathException e) {
            return new Found(null, "the reference trace " + written + " is not a file name: " + e.getReason(), false);
        }
        String shown = written + " (" + file + ")";
        Trace trace;
        try {
            if (!Files.isRegularFile(file)) {
                return new Found(null, "the reference trace " + shown + " does not exist", false);
            }
            if (Files.size(file) > MAX_BYTES) {
                return new Found(null, "the reference trace " + shown + " is " + Files.size(file) + " bytes, more than "
                        + MAX_BYTES + " bytes a reference may have", false);
            }
            trace = TraceReader.read(file).trace();
        } catch (IOException e) {
            return new Found(null, "the reference trace " + shown + " cannot be read: " + IoText.describe(e), false);
        } catch (RuntimeException e) {
            // Gson's and the reader's complaints about a document that is JSON but not a trace (a missing or
            // mistyped field): the file's fault, named as such.
            return new Found(null, "the reference trace " + shown + " is not an emini-trace: " + e.getMessage(), false);
        }
        if (!trace.has(channel)) {
            return new Found(null, "the reference trace " + written + " has no channel " + channel + " (it has "
                    + known(trace) + ")", true);
        }
        long[] ticks = new long[trace.size()];
        for (int i = 0; i < ticks.length; i++) {
            ticks[i] = trace.tick(i);
        }
        if (ticks.length == 0) {
            return new Found(null, "the reference trace " + written + " has no samples", false);
        }
        return new Found(new ReferenceTrace(written, channel, trace.timestep(), ticks, trace.column(channel)), null, false);
    }

    /** The ticks a scene samples: 0, every {@code record.every} rounded to ticks, and the last (ScenarioRunner). */
    static long[] sampleTicks(Scenario s) {
        long n = s.ticks();
        long every = s.run().record().samplingTicks(s.world().timestep());
        List<Long> out = new ArrayList<>();
        out.add(0L);
        for (long k = 0; k < n; k++) {
            if ((k + 1) % every == 0 || k + 1 == n) {
                out.add(k + 1);
            }
        }
        return out.stream().mapToLong(Long::longValue).toArray();
    }

    private static String known(Trace t) {
        List<String> c = new ArrayList<>(t.channels());
        return c.size() <= 12 ? String.join(", ", c) : String.join(", ", c.subList(0, 12)) + ", … " + c.size() + " in all";
    }
}
