package org.emini.harness.oracle;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.emini.harness.metrics.PenetrationPair;
import org.emini.harness.run.Trace;

/**
 * Reads a trace file (harness/README.md, Trace format version 1) back into a {@link Trace}, whoever
 * wrote it: the harness ({@code source: emini}) or the oracle ({@code source: pymunk}). Null values
 * (NaN or infinity) come back as NaN; fields the reader does not know are ignored.
 */
public final class TraceReader {
    private TraceReader() {
    }

    /**
     * A trace read from disk.
     *
     * @param scene the scene id
     * @param source who wrote it
     * @param trace the samples
     */
    public record Read(String scene, String source, Trace trace) {
    }

    /** Reads a trace file; refuses another format or version. */
    public static Read read(Path file) throws IOException {
        try (Reader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            return parse(JsonParser.parseReader(in).getAsJsonObject(), file.toString());
        }
    }

    /**
     * Reads a trace document already parsed (the oracle's sweep answers carry their trace inline).
     *
     * @param doc the trace
     * @param shown how to name it in errors
     */
    public static Read parse(JsonObject doc, String shown) throws IOException {
        if (!"emini-trace".equals(string(doc, "format")) || doc.get("version") == null
                || doc.get("version").getAsInt() != 1) {
            throw new IOException(shown + ": not an emini-trace version 1");
        }
        double timestep = doc.get("timestep").getAsDouble();
        JsonArray ticks = doc.getAsJsonArray("tick");
        JsonObject bodies = doc.getAsJsonObject("bodies");
        JsonObject metrics = doc.getAsJsonObject("metrics");
        List<String> bodyNames = new ArrayList<>(bodies.keySet());
        List<String> metricChannels = new ArrayList<>(metrics.keySet());
        // Runs that let bodies sleep add a column "sleeping" (1 while asleep) to every body.
        boolean sleeping = !bodyNames.isEmpty() && bodies.getAsJsonObject(bodyNames.get(0)).has("sleeping");
        Trace trace = new Trace(timestep, bodyNames, metricChannels, sleeping);
        List<JsonArray> columns = new ArrayList<>();
        List<JsonArray> asleep = new ArrayList<>();
        for (String b : bodyNames) {
            JsonObject body = bodies.getAsJsonObject(b);
            if (sleeping) {
                JsonArray c = body.getAsJsonArray("sleeping");
                if (c == null || c.size() != ticks.size()) {
                    throw new IOException(shown + ": body " + b + " has no sleeping column of " + ticks.size()
                            + " values, as the first body has");
                }
                asleep.add(c);
            }
            for (String f : Trace.BODY_FIELDS) {
                JsonArray c = body.getAsJsonArray(f);
                if (c == null) {
                    throw new IOException(shown + ": body " + b + " has no column " + f);
                }
                columns.add(c);
            }
        }
        for (Map.Entry<String, JsonElement> m : metrics.entrySet()) {
            columns.add(m.getValue().getAsJsonArray());
        }
        for (int i = 0; i < ticks.size(); i++) {
            double[] row = new double[columns.size()];
            for (int c = 0; c < row.length; c++) {
                JsonArray col = columns.get(c);
                if (col.size() != ticks.size()) {
                    throw new IOException(shown + ": column " + trace.channels().get(c) + " has " + col.size()
                            + " values for " + ticks.size() + " samples");
                }
                JsonElement v = col.get(i);
                row[c] = v.isJsonNull() ? Double.NaN : v.getAsDouble();
            }
            if (!sleeping) {
                trace.add(ticks.get(i).getAsLong(), row);
                continue;
            }
            boolean[] flags = new boolean[asleep.size()];
            for (int b = 0; b < flags.length; b++) {
                flags[b] = asleep.get(b).get(i).getAsInt() != 0;
            }
            trace.add(ticks.get(i).getAsLong(), row, flags);
        }
        JsonArray pairs = doc.getAsJsonArray("penetrationPairs");
        if (pairs != null) {
            List<PenetrationPair> list = new ArrayList<>();
            for (JsonElement e : pairs) {
                JsonObject p = e.getAsJsonObject();
                list.add(new PenetrationPair(string(p, "a"), string(p, "b"), number(p, "max"), number(p, "mean"),
                        p.get("samples").getAsInt()));
            }
            trace.setPenetrationPairs(list);
        }
        return new Read(string(doc, "scene"), string(doc, "source"), trace);
    }

    private static double number(JsonObject o, String key) {
        JsonElement e = o.get(key);
        return e == null || e.isJsonNull() ? Double.NaN : e.getAsDouble();
    }

    private static String string(JsonObject o, String key) {
        JsonElement e = o.get(key);
        return e == null || e.isJsonNull() ? null : e.getAsString();
    }
}
