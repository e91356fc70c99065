package org.emini.harness.sweep;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The sweep's results file: one JSON object per line and point, appended as each point completes
 * (under a file lock, so shards on one machine can share it). A sweep that starts again skips the
 * points already in it; shards run on other machines are merged by concatenating their files. A
 * later line for the same point replaces an earlier one; a torn last line is ignored.
 */
public final class PointStore {
    private final Path file;

    /** @param file the results file (created on first append) */
    public PointStore(Path file) {
        this.file = file;
    }

    /** The file. */
    public Path file() {
        return file;
    }

    /** Every point in the file, by key. */
    public Map<String, SweepPoint> load() throws IOException {
        Map<String, SweepPoint> out = new LinkedHashMap<>();
        if (!Files.isRegularFile(file)) {
            return out;
        }
        for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
            if (line.isBlank()) {
                continue;
            }
            try {
                SweepPoint p = parse(JsonParser.parseString(line).getAsJsonObject());
                out.put(p.key(), p);
            } catch (RuntimeException e) {
                // an interrupted write leaves a partial line: that point is simply run again
            }
        }
        return out;
    }

    /**
     * The keys of the points a resumed sweep skips: every point in the file except those that ended in
     * {@code error} (an oracle process that died or timed out, say), which are run again.
     */
    public java.util.Set<String> completed() throws IOException {
        java.util.Set<String> out = new java.util.LinkedHashSet<>();
        for (SweepPoint p : load().values()) {
            if (!p.status().equals("error")) {
                out.add(p.key());
            }
        }
        return out;
    }

    /** Appends one point. */
    public synchronized void append(SweepPoint p) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        byte[] line = (json(p) + "\n").getBytes(StandardCharsets.UTF_8);
        try (RandomAccessFile raf = new RandomAccessFile(file.toFile(), "rw");
             FileChannel ch = raf.getChannel();
             FileLock lock = ch.lock()) {
            long size = ch.size();
            if (size > 0) {
                // An interrupted write leaves a line without its newline: end it, so this point is not lost with it.
                ByteBuffer last = ByteBuffer.allocate(1);
                ch.read(last, size - 1);
                if (last.get(0) != '\n') {
                    ch.write(ByteBuffer.wrap(new byte[] {'\n'}), size++);
                }
            }
            ch.write(ByteBuffer.wrap(line), size);
            ch.force(false);
        }
    }

    /** All points of every {@code *.jsonl} file in a folder (merged shards). */
    public static List<SweepPoint> loadAll(Path dir) throws IOException {
        Map<String, SweepPoint> out = new LinkedHashMap<>();
        if (Files.isDirectory(dir)) {
            try (var files = Files.list(dir)) {
                for (Path f : files.filter(x -> x.toString().endsWith(".jsonl")).sorted().toList()) {
                    out.putAll(new PointStore(f).load());
                }
            }
        }
        return new ArrayList<>(out.values());
    }

    /** One point as a JSON line (non-finite figures as null). */
    public static String json(SweepPoint p) {
        JsonObject o = new JsonObject();
        o.addProperty("scene", p.scene());
        o.addProperty("engine", p.engine());
        o.addProperty("rate", p.rate());
        o.addProperty("iterations", p.iterations());
        o.addProperty("status", p.status());
        o.addProperty("message", p.message());
        o.addProperty("reference", p.reference());
        num(o, "finalError", p.finalError());
        num(o, "maxError", p.maxError());
        num(o, "rmsError", p.rmsError());
        num(o, "costSeconds", p.costSeconds());
        num(o, "cpuCostSeconds", p.cpuCostSeconds());
        o.addProperty("repeats", p.repeats());
        num(o, "energyDrift", p.energyDrift());
        num(o, "momentumDrift", p.momentumDrift());
        num(o, "motion", p.motion());
        num(o, "relativeError", p.relativeError());
        return o.toString();
    }

    private static void num(JsonObject o, String k, double v) {
        if (Double.isFinite(v)) {
            o.addProperty(k, v);
        } else {
            o.add(k, com.google.gson.JsonNull.INSTANCE);
        }
    }

    private static double d(JsonObject o, String k) {
        JsonElement e = o.get(k);
        return e == null || e.isJsonNull() ? Double.NaN : e.getAsDouble();
    }

    private static String s(JsonObject o, String k) {
        JsonElement e = o.get(k);
        return e == null || e.isJsonNull() ? "" : e.getAsString();
    }

    static SweepPoint parse(JsonObject o) {
        return new SweepPoint(s(o, "scene"), s(o, "engine"), o.get("rate").getAsInt(), o.get("iterations").getAsInt(),
                s(o, "status"), s(o, "message"), s(o, "reference"), d(o, "finalError"), d(o, "maxError"),
                d(o, "rmsError"), d(o, "costSeconds"), o.get("repeats").getAsInt(), d(o, "energyDrift"),
                d(o, "momentumDrift"), d(o, "motion"), d(o, "cpuCostSeconds"));
    }
}
