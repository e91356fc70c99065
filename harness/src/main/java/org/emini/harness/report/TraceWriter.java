package org.emini.harness.report;

import com.google.gson.stream.JsonWriter;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.emini.harness.metrics.PenetrationPair;
import org.emini.harness.run.Trace;
import org.emini.harness.scenario.Channels;

/**
 * Writes a trace as JSON in the format of harness/README.md (Trace format): columns per body quantity
 * and per metric channel, NaN and infinities as null. The Python oracle (oracle-py/) writes the same
 * format, so its traces and ours compare column by column.
 */
public final class TraceWriter {
    /** Version of the trace format; bump on any incompatible change. */
    public static final int VERSION = 1;

    private TraceWriter() {
    }

    /** The trace file name of a scene: its id with '/' kept as folders. */
    public static Path fileFor(Path tracesDir, String scene) {
        return tracesDir.resolve(scene + ".trace.json");
    }

    /** The replay file of a scene ({@code ReplayRecorder}), beside its trace. */
    public static Path replayFor(Path tracesDir, String scene) {
        return tracesDir.resolve(scene + ".replay.json");
    }

    /** Writes a replay (the dashboard's frames of a run). */
    public static void writeReplay(Path file, com.google.gson.JsonObject replay) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        Files.writeString(file, replay.toString(), StandardCharsets.UTF_8);
    }

    /**
     * Writes a trace.
     *
     * @param file the file (folders are created)
     * @param scene the scene id
     * @param source who produced it ({@code emini}; the oracle writes {@code pymunk})
     * @param trace the samples
     */
    public static void write(Path file, String scene, String source, Trace trace) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        try (Writer out = new BufferedWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8), 1 << 16)) {
            write(out, scene, source, trace);
        }
    }

    /** Writes a trace to a stream. */
    public static void write(Writer out, String scene, String source, Trace trace) throws IOException {
        JsonWriter json = new JsonWriter(out);
        json.beginObject();
        json.name("format").value("emini-trace");
        json.name("version").value(VERSION);
        json.name("scene").value(scene);
        json.name("source").value(source);
        json.name("timestep").value(trace.timestep());
        json.name("tick").beginArray();
        for (int i = 0; i < trace.size(); i++) {
            json.value(trace.tick(i));
        }
        json.endArray();
        json.name("time").beginArray();
        for (int i = 0; i < trace.size(); i++) {
            number(json, trace.time(i), false);
        }
        json.endArray();
        json.name("bodies").beginObject();
        for (int b = 0; b < trace.bodies().size(); b++) {
            String body = trace.bodies().get(b);
            json.name(body).beginObject();
            for (String field : Trace.BODY_FIELDS) {
                json.name(field);
                column(json, trace.column(Channels.body(body, field)), true);
            }
            if (trace.recordsSleeping()) {
                // 1 while the body sleeps; only in runs that let bodies sleep (readers ignore unknown fields).
                json.name("sleeping").beginArray();
                for (int i = 0; i < trace.size(); i++) {
                    json.value(trace.sleeping(i, b) ? 1 : 0);
                }
                json.endArray();
            }
            json.endObject();
        }
        json.endObject();
        json.name("metrics").beginObject();
        for (String channel : trace.metricChannels()) {
            json.name(channel);
            column(json, trace.column(channel), false);
        }
        json.endObject();
        if (!trace.penetrationPairs().isEmpty()) {
            json.name("penetrationPairs");
            pairs(json, trace.penetrationPairs());
        }
        json.endObject();
        json.flush();
    }

    /** Penetration per pair: {@code [{a, b, max, mean, samples}]}, as results.json and the trace write it. */
    static void pairs(JsonWriter json, List<PenetrationPair> pairs) throws IOException {
        json.beginArray();
        for (PenetrationPair p : pairs) {
            json.beginObject();
            json.name("a").value(p.a());
            json.name("b").value(p.b());
            json.name("max");
            number(json, p.max(), false);
            json.name("mean");
            number(json, p.mean(), false);
            json.name("samples").value(p.samples());
            json.endObject();
        }
        json.endArray();
    }

    private static void column(JsonWriter json, double[] values, boolean singlePrecision) throws IOException {
        json.beginArray();
        for (double v : values) {
            number(json, v, singlePrecision);
        }
        json.endArray();
    }

    // Body state comes from the engine's floats: print it at float precision (shortest float text),
    // which is exact and about half the size of the double's 17 digits.
    private static void number(JsonWriter json, double v, boolean singlePrecision) throws IOException {
        if (!Double.isFinite(v)) {
            json.nullValue();
        } else if (singlePrecision) {
            json.value(Float.valueOf((float) v));
        } else {
            json.value(v);
        }
    }
}
