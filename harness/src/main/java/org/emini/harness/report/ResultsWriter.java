package org.emini.harness.report;

import com.google.gson.stream.JsonWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import org.emini.harness.expect.Verdict;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.StateHash;
import org.emini.harness.scenario.KnownFailure;
import org.emini.harness.scenario.Scenario;

/** Writes {@code results.json}: the summary and every scene's status and figures (harness/README.md). */
public final class ResultsWriter {
    private ResultsWriter() {
    }

    /**
     * Writes the results.
     *
     * @param file results.json
     * @param results the scenes' results, in run order
     * @param summary the counts
     * @param traces the folder the traces went to (for relative links), or null if none were written
     */
    public static void write(Path file, List<SceneResult> results, Summary summary, Path traces) throws IOException {
        write(file, results, summary, traces, null, null, 1);
    }

    /**
     * Writes the results of a run that forced sleeping on or off ({@code run --sleeping}), nudged every
     * scene ({@code run --nudge}) or shared every scene's ticks among threads ({@code run --workers}).
     *
     * @param sleeping {@code on} or {@code off} as forced, or null when each scene had its own setting
     * @param nudge the nudge of every scene (its speculative distance times it, and gravity times
     *     {@link Scenario#gravityNudge}, written beside it as {@code nudgeGravity}), or null for none
     * @param workers the threads every scene's world shared its ticks among (written when more than 1)
     */
    public static void write(Path file, List<SceneResult> results, Summary summary, Path traces, String sleeping,
            Double nudge, int workers) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            JsonWriter json = new JsonWriter(out);
            json.setIndent("  ");
            json.beginObject();
            json.name("format").value("emini-results");
            json.name("version").value(1);
            json.name("generated").value(Instant.now().toString());
            if (sleeping != null) {
                json.name("sleeping").value(sleeping);
            }
            if (nudge != null) {
                json.name("nudge").value(nudge);
                json.name("nudgeGravity").value(Scenario.gravityNudge(nudge));
            }
            if (workers > 1) {
                json.name("workers").value(workers);
            }
            json.name("summary").beginObject();
            json.name("scenes").value(summary.total());
            json.name("pass").value(summary.pass());
            json.name("knownFailure").value(summary.known());
            json.name("fail").value(summary.fail());
            json.name("unsupported").value(summary.unsupported());
            json.name("error").value(summary.error());
            json.name("staleKnownFailures").value(summary.stale());
            json.name("seconds").value(summary.seconds());
            json.endObject();
            json.name("scenes").beginArray();
            Path base = file.toAbsolutePath().getParent();
            for (SceneResult r : results) {
                scene(json, r, traces == null ? null : base.relativize(TraceWriter.fileFor(traces.toAbsolutePath(), r.scene())));
            }
            json.endArray();
            json.endObject();
        }
    }

    private static void scene(JsonWriter json, SceneResult r, Path trace) throws IOException {
        json.beginObject();
        json.name("scene").value(r.scene());
        json.name("file").value(r.file());
        json.name("category").value(r.category());
        json.name("status").value(r.status().label());
        json.name("message").value(r.message());
        json.name("bodies").value(r.bodies());
        json.name("ticks").value(r.ticks());
        json.name("timestep").value(r.timestep());
        json.name("buildMillis").value(round(r.buildMillis()));
        json.name("runMillis").value(round(r.runMillis()));
        if (r.ticks() > 0) {
            json.name("microsPerTick").value(round(r.microsPerTick()));
        }
        if (r.stateHash() != null) {
            json.name("stateHash").value(StateHash.hex(r.stateHash()));
        }
        if (r.mostAsleep() >= 0) {
            json.name("mostAsleep").value(r.mostAsleep());
        }
        if (!r.penetrationPairs().isEmpty()) {
            json.name("penetrationPairs");
            TraceWriter.pairs(json, r.penetrationPairs());
        }
        if (trace != null && r.ticks() > 0) {
            json.name("trace").value(trace.toString().replace('\\', '/'));
        }
        if (r.knownFailure() != null) {
            json.name("knownFailure");
            known(json, r.knownFailure());
        }
        json.name("staleKnownFailures").beginArray();
        for (String s : r.staleKnownFailures()) {
            json.value(s);
        }
        json.endArray();
        json.name("expectations").beginArray();
        for (Verdict v : r.verdicts()) {
            json.beginObject();
            json.name("expectation").value(v.expectation());
            json.name("passed").value(v.passed());
            json.name("measured");
            if (Double.isFinite(v.measured())) {
                json.value(v.measured());
            } else {
                json.nullValue();
            }
            json.name("detail").value(v.detail());
            if (v.knownFailure() != null) {
                json.name("knownFailure");
                known(json, v.knownFailure());
            }
            json.endObject();
        }
        json.endArray();
        json.endObject();
    }

    private static void known(JsonWriter json, KnownFailure k) throws IOException {
        json.beginObject();
        json.name("reason").value(k.reason());
        json.name("measured").value(k.measured());
        if (k.issue() != null) {
            json.name("issue").value(k.issue());
        }
        json.endObject();
    }

    private static double round(double ms) {
        return Math.round(ms * 1000) / 1000.0;
    }
}
