package org.emini.bench.run;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import com.google.gson.reflect.TypeToken;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.emini.bench.check.Stability;
import org.emini.bench.engine.PeerSceneExport;
import org.emini.bench.engine.UnsupportedSceneException;
import org.emini.bench.scene.BenchScenes;
import org.emini.harness.oracle.OracleEnvironment;
import org.emini.harness.scenario.Scenario;

/**
 * The engines timed in a process of their own, each by a driver that follows
 * {@code bench/peers/peer_bench.py}'s method (the JMH benchmark's: preroll, check, warm-up and
 * measurement rounds, the thread's CPU time per tick) and writes its result file: pymunk through the
 * oracle's scene reader and builder (px), Box2D v3 through the PyPI package pyb2d3 and Rapier through a
 * small Rust program, both from the flat scene {@link PeerSceneExport} writes (metres, the Java Box2D
 * peers' mapping). This class makes a driver's environment on first use (a virtual environment from
 * pinned requirements, or {@code cargo build --release --locked}), runs it, and judges the poses it
 * reported with the benchmark's one scene check ({@link Stability}). An engine whose environment cannot
 * be made (no network, no Python or cargo) is reported {@code missing}, with the reason, on every scene.
 */
final class ExternalBench {
    /** The out-of-process engines, in the report's order. */
    static final List<String> IDS = List.of("pymunk", "box2d-v3", "rapier");

    /** What a run found: status, message, and the measurements (scene ids as asked). */
    record Outcome(String engine, String status, String message, List<Measurement> measurements, boolean kept) {
        Map<String, Object> summary() {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("status", status);
            m.put("message", message);
            return m;
        }
    }

    /** The driver's environment cannot be made; the message says why. */
    private static final class MissingException extends Exception {
        MissingException(String message) {
            super(message);
        }
    }

    /**
     * One driver.
     *
     * @param id the engine id
     * @param message what the figures are, for the report
     * @param exportVertices the engine's polygon vertex limit for the flat export, or 0 for a driver that
     *     reads the scene files itself
     */
    private record Driver(String id, String message, int exportVertices) {
    }

    private static Driver driver(String id) {
        switch (id) {
            case "pymunk":
                return new Driver(id, "pymunk timed from Python with the oracle's builder (bench/pymunk/pymunk_bench.py): "
                    + "CPU time of the Python thread per tick; no allocation figure", 0);
            case "box2d-v3":
                return new Driver(id, "Box2D v3.1.1 timed from Python through pyb2d3 (bench/box2d/box2d_bench.py, one call "
                    + "into the C library per tick): CPU time of the thread per tick; no allocation figure", 8);
            case "rapier":
                return new Driver(id, "Rapier timed by a Rust program (bench/rapier): CPU time of the thread per tick; "
                    + "no allocation figure", Integer.MAX_VALUE);
            default:
                throw new IllegalArgumentException("unknown out-of-process engine " + id + "; known: " + IDS);
        }
    }

    private ExternalBench() {
    }

    /**
     * Times an engine on the scenes, or with {@code resume} reuses the result file an earlier run left in
     * {@code out} when it has every one of them.
     */
    static Outcome run(String engine, BenchScenes scenes, BenchPlan.Mode mode, Path out, List<String> sceneIds, boolean resume) {
        Driver d = driver(engine);
        if (sceneIds.isEmpty()) {
            return new Outcome(engine, "skipped", "no scene to time", List.of(), false);
        }
        Path root = scenes.root();
        Path result = out.resolve(engine + ".json");
        Path exports = out.resolve("peer-scenes").resolve(engine);
        // Scenes the flat export refuses are reported here; the driver gets the others.
        Map<String, Measurement> refused = new LinkedHashMap<>();
        List<String> toRun = new ArrayList<>();
        try {
            for (String id : sceneIds) {
                if (d.exportVertices() == 0) {
                    toRun.add(id);
                    continue;
                }
                try {
                    JsonObject json = PeerSceneExport.toJson(id, scenes.load(id), engine, d.exportVertices());
                    Path f = exports.resolve(id + ".json");
                    Files.createDirectories(f.getParent());
                    Files.writeString(f, json.toString(), StandardCharsets.UTF_8);
                    toRun.add(id);
                } catch (UnsupportedSceneException e) {
                    refused.put(id, Measurement.notRun(id, engine, "unsupported", e.getMessage()));
                }
            }
            if (resume) {
                List<Measurement> kept = kept(engine, result, scenes, toRun);
                if (kept != null) {
                    return new Outcome(engine, "ran", d.message() + " (kept from an earlier run by --resume)",
                        inOrder(engine, sceneIds, kept, refused), true);
                }
            }
            List<Measurement> measured = List.of();
            if (!toRun.isEmpty()) {
                List<String> cmd = new ArrayList<>(command(engine, root, out));
                cmd.addAll(List.of("--out", result.toString()));
                if (d.exportVertices() != 0) {
                    cmd.addAll(List.of("--scenes-dir", exports.toString()));
                }
                if (mode.quick()) {
                    cmd.addAll(List.of("--preroll", Integer.toString(mode.preroll()), "--warmups", "1", "--iterations", "2",
                        "--seconds", "0.15"));
                } else {
                    cmd.addAll(List.of("--warmups", Integer.toString(mode.warmups()), "--iterations",
                        Integer.toString(mode.iterations()), "--seconds", Double.toString(mode.iterationMillis() / 1000.0)));
                }
                cmd.addAll(toRun);
                Files.deleteIfExists(result);
                Process p = new ProcessBuilder(cmd).inheritIO().start();
                if (!p.waitFor(3, TimeUnit.HOURS) || p.exitValue() != 0 || !Files.isRegularFile(result)) {
                    p.destroy();
                    return new Outcome(engine, "error", "the " + engine + " driver failed (exit "
                        + (p.isAlive() ? "timeout" : p.exitValue()) + "): " + String.join(" ", cmd), List.of(), false);
                }
                measured = measurements(engine, read(result), scenes, toRun);
            }
            return new Outcome(engine, "ran", d.message(), inOrder(engine, sceneIds, measured, refused), false);
        } catch (MissingException e) {
            List<Measurement> missing = new ArrayList<>();
            for (String id : sceneIds) {
                missing.add(Measurement.notRun(id, engine, "missing", e.getMessage()));
            }
            return new Outcome(engine, "missing", e.getMessage(), missing, false);
        } catch (IOException | RuntimeException e) {
            return new Outcome(engine, "error", "cannot run " + engine + ": " + e, List.of(), false);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return new Outcome(engine, "error", "interrupted", List.of(), false);
        }
    }

    private static List<Measurement> inOrder(String engine, List<String> sceneIds, List<Measurement> measured,
                                             Map<String, Measurement> refused) {
        List<Measurement> all = new ArrayList<>();
        for (String id : sceneIds) {
            Measurement m = refused.get(id);
            if (m == null) {
                m = measured.stream().filter(x -> id.equals(x.scene())).findFirst()
                    .orElse(Measurement.notRun(id, engine, "error", "no result"));
            }
            all.add(m);
        }
        return all;
    }

    /** The command that starts an engine's driver, its environment made first when missing. */
    private static List<String> command(String engine, Path root, Path out) throws MissingException, InterruptedException {
        switch (engine) {
            case "pymunk": {
                Path oracle = root.resolve("oracle-py");
                if (!Files.isDirectory(oracle)) {
                    throw new MissingException("the pymunk oracle (oracle-py/) is not in this checkout");
                }
                return List.of(python(oracle).toString(), root.resolve("bench/pymunk/pymunk_bench.py").toString(),
                    "--root", root.toString());
            }
            case "box2d-v3": {
                Path box2d = root.resolve("bench").resolve("box2d");
                return List.of(python(box2d).toString(), box2d.resolve("box2d_bench.py").toString());
            }
            default: {
                return List.of(rapier(root.resolve("bench").resolve("rapier"), out).toString());
            }
        }
    }

    /** A Python project's environment (the oracle's, or bench/box2d's), made from its pinned requirements. */
    private static Path python(Path project) throws MissingException {
        try {
            return new OracleEnvironment(project, OracleEnvironment.defaultPython()).ensure(System.err);
        } catch (IOException e) {
            throw new MissingException("cannot make " + project.getParent().getFileName() + "/" + project.getFileName()
                + "/.venv from its pinned requirements (no network, or no Python 3 with venv?): " + firstLines(e.getMessage()));
        }
    }

    /** The Rapier driver, built with cargo from the committed Cargo.lock (cargo skips the build when it is current). */
    private static Path rapier(Path project, Path out) throws MissingException, InterruptedException {
        Path binary = project.resolve("target").resolve("release").resolve("emini-rapier-bench");
        String cargo = System.getenv().getOrDefault("EMINI_CARGO", "cargo");
        Path log = out.resolve("rapier-build.log");
        try {
            Files.createDirectories(out);
            Process p = new ProcessBuilder(cargo, "build", "--release", "--locked", "--quiet").directory(project.toFile())
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
            if (p.waitFor() != 0) {
                throw new MissingException("cargo build --release --locked in bench/rapier failed (exit " + p.exitValue()
                    + "; no network for crates.io?): " + firstLines(Files.readString(log, StandardCharsets.UTF_8)) + " (see " + log + ")");
            }
        } catch (IOException e) {
            throw new MissingException("cannot run " + cargo + " to build bench/rapier (Rust's cargo is needed; set EMINI_CARGO "
                + "to choose it): " + e.getMessage());
        }
        if (!Files.isExecutable(binary)) {
            throw new MissingException("cargo built bench/rapier but " + binary + " is not there");
        }
        return binary;
    }

    private static String firstLines(String s) {
        String[] lines = s == null ? new String[0] : s.strip().split("\n");
        return String.join(" / ", java.util.Arrays.asList(lines).subList(0, Math.min(3, lines.length)));
    }

    private static JsonArray read(Path result) throws IOException {
        return JsonParser.parseString(Files.readString(result, StandardCharsets.UTF_8)).getAsJsonArray();
    }

    /**
     * The kept results of exactly these scenes, judged, or null unless the file has every one of them
     * measured (or refused as unsupported, which a new run would repeat).
     */
    static List<Measurement> kept(String engine, Path result, BenchScenes scenes, List<String> sceneIds) {
        if (!Files.isRegularFile(result)) {
            return null;
        }
        try {
            JsonArray all = read(result);
            for (String id : sceneIds) {
                JsonObject e = entry(all, id);
                String status = e == null ? null : str(e, "status");
                if (!"ok".equals(status) && !"unsupported".equals(status)) {
                    return null;
                }
            }
            return measurements(engine, all, scenes, sceneIds);
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    private static JsonObject entry(JsonArray all, String id) {
        for (JsonElement x : all) {
            if (x.isJsonObject() && id.equals(str(x.getAsJsonObject(), "scene"))) {
                return x.getAsJsonObject();
            }
        }
        return null;
    }

    /** The driver's entries of these scenes as measurements, their snapshots judged. */
    private static List<Measurement> measurements(String engine, JsonArray all, BenchScenes scenes, List<String> sceneIds) {
        List<Measurement> out = new ArrayList<>();
        for (String id : sceneIds) {
            JsonObject e = entry(all, id);
            out.add(e == null ? Measurement.notRun(id, engine, "error", "the driver wrote no result for this scene")
                : measurement(e, scenes.load(id)));
        }
        return out;
    }

    /** One driver entry as a measurement: its figures, and the scene check of its snapshots. */
    static Measurement measurement(JsonObject e, Scenario s) {
        String scene = str(e, "scene"), engine = str(e, "engine");
        if (!"ok".equals(str(e, "status"))) {
            return Measurement.notRun(scene, engine, str(e, "status"), str(e, "message"));
        }
        boolean metres = "m".equals(str(e, "units"));
        double[] initial = snapshot(e.getAsJsonObject("initial"), s, metres).poses;
        Map<String, Object> check = judged(e.getAsJsonObject("check"), s, initial, metres);
        Map<String, Object> after = judged(e.getAsJsonObject("afterRun"), s, initial, metres);
        long dynamic = Stability.moving(s);
        double cpu = e.get("cpuMsPerTick").getAsDouble();
        return new Measurement(scene, engine, "ok", "", s.bodies().size(), dynamic, num(e, "msPerTick"), num(e, "msPerTickError"),
            num(e, "msPerTickMedian"), cpu, cpu * 1000.0 / Math.max(1, dynamic), null, null, num(e, "prerollMsPerTick"),
            str(e, "settings"), check, after);
    }

    /** A driver's snapshot in the scene's units. */
    private record Snapshot(long ticks, double[] poses, double[] speeds, double[] omegas, double[] particles, int asleep) {
    }

    private static Snapshot snapshot(JsonObject o, Scenario s, boolean metres) {
        double[] poses = doubles(o, "poses");
        double[] speeds = doubles(o, "speeds");
        double[] omegas = doubles(o, "omegas");
        double[] particles = doubles(o, "particles");
        int n = s.bodies().size();
        if (poses.length != 3 * n || speeds.length != n || omegas.length != n || particles.length % 2 != 0) {
            throw new IllegalArgumentException("the driver reported " + poses.length / 3 + " poses, " + speeds.length + " speeds and "
                + omegas.length + " angular velocities for a scene of " + n + " bodies");
        }
        if (metres) {
            PeerSceneExport.toScene(poses, speeds, omegas, particles);
        }
        return new Snapshot(o.get("ticks").getAsLong(), poses, speeds, omegas, particles, o.get("asleep").getAsInt());
    }

    private static Map<String, Object> judged(JsonObject o, Scenario s, double[] initial, boolean metres) {
        Snapshot now = snapshot(o, s, metres);
        Stability st = Stability.judge(s, now.ticks(), initial, now.poses(), now.speeds(), now.omegas(), now.particles(),
            now.particles().length / 2).withAsleep(now.asleep());
        Gson gson = new GsonBuilder().serializeSpecialFloatingPointValues().create();
        return gson.fromJson(gson.toJsonTree(st), new TypeToken<Map<String, Object>>() { }.getType());
    }

    /** A number array; null (JSON's stand-in for a non-finite figure) reads as NaN. */
    private static double[] doubles(JsonObject o, String key) {
        JsonArray a = o.getAsJsonArray(key);
        double[] out = new double[a.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = a.get(i).isJsonNull() ? Double.NaN : a.get(i).getAsDouble();
        }
        return out;
    }

    private static Double num(JsonObject o, String key) {
        JsonElement x = o.get(key);
        return x == null || x.isJsonNull() ? null : x.getAsDouble();
    }

    private static String str(JsonObject o, String key) {
        JsonElement x = o.get(key);
        return x == null || x.isJsonNull() ? null : x.getAsString();
    }
}
