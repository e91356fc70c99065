package org.emini.bench.run;

import com.google.gson.Gson;
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
import org.emini.bench.scene.BenchScenes;

/**
 * pymunk, timed from Python through the oracle's scene reader and builder (issue 6) by
 * {@code bench/pymunk/pymunk_bench.py}, with the oracle's environment ({@code oracle-py/.venv}, made
 * the way the harness makes it when missing). Until {@code oracle-py/} is in the repository there is
 * nothing to time pymunk with, and the report says so.
 */
final class PymunkBench {
    /** What the run found: status, message, and the measurements (scene ids as asked). */
    record Outcome(String status, String message, List<Measurement> measurements, boolean kept) {
        Outcome(String status, String message, List<Measurement> measurements) {
            this(status, message, measurements, false);
        }

        Map<String, Object> summary() {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("status", status);
            m.put("message", message);
            return m;
        }
    }

    private static final String MESSAGE = "pymunk timed from Python with the oracle's builder (bench/pymunk/pymunk_bench.py): "
        + "CPU time of the Python process per tick; no allocation figure";

    private PymunkBench() {
    }

    private static List<Measurement> read(Path result) throws IOException {
        return new Gson().fromJson(Files.readString(result, StandardCharsets.UTF_8), new TypeToken<List<Measurement>>() { }.getType());
    }

    /** The kept measurements of exactly these scenes, or null unless the file has them all. */
    static List<Measurement> kept(Path result, List<String> sceneIds) {
        if (!Files.isRegularFile(result)) {
            return null;
        }
        List<Measurement> all;
        try {
            all = read(result);
        } catch (IOException | RuntimeException e) {
            return null;
        }
        if (all == null) {
            return null;
        }
        List<Measurement> out = new ArrayList<>();
        for (String id : sceneIds) {
            Measurement m = all.stream().filter(x -> id.equals(x.scene())).findFirst().orElse(null);
            if (m == null || !"ok".equals(m.status())) {
                return null;
            }
            out.add(m);
        }
        return out;
    }

    /**
     * Times pymunk on the scenes, or with {@code resume} reuses the {@code pymunk.json} an earlier run
     * left in {@code out} when it has every one of them.
     */
    static Outcome run(BenchScenes scenes, BenchPlan.Mode mode, Path out, List<String> sceneIds, boolean resume) {
        Path root = scenes.root();
        Path oracle = root.resolve("oracle-py");
        if (!Files.isDirectory(oracle)) {
            return new Outcome("pending", "the pymunk oracle (oracle-py/, branch oracle) has not landed on main yet; "
                + "pymunk will be timed with its scene builder once it has", List.of());
        }
        if (sceneIds.isEmpty()) {
            return new Outcome("skipped", "no scene to time", List.of());
        }
        Path result = out.resolve("pymunk.json");
        if (resume) {
            List<Measurement> kept = kept(result, sceneIds);
            if (kept != null) {
                return new Outcome("ran", MESSAGE + " (kept from an earlier run by --resume)", kept, true);
            }
        }
        try {
            Path python = environment(oracle, out);
            Files.deleteIfExists(result);
            List<String> cmd = new ArrayList<>(List.of(python.toString(), root.resolve("bench/pymunk/pymunk_bench.py").toString(),
                "--root", root.toString(), "--out", result.toString()));
            if (mode.quick()) {
                cmd.addAll(List.of("--preroll", Integer.toString(mode.preroll()), "--warmups", "1", "--iterations", "2", "--seconds", "0.15"));
            } else {
                cmd.addAll(List.of("--warmups", Integer.toString(mode.warmups()), "--iterations", Integer.toString(mode.iterations()),
                    "--seconds", Double.toString(mode.iterationMillis() / 1000.0)));
            }
            cmd.addAll(sceneIds);
            Process p = new ProcessBuilder(cmd).inheritIO().start();
            if (!p.waitFor(3, TimeUnit.HOURS) || p.exitValue() != 0 || !Files.isRegularFile(result)) {
                p.destroy();
                return new Outcome("error", "pymunk_bench.py failed (exit " + (p.isAlive() ? "timeout" : p.exitValue()) + ")", List.of());
            }
            return new Outcome("ran", MESSAGE, read(result));
        } catch (IOException e) {
            return new Outcome("error", "cannot run pymunk: " + e.getMessage(), List.of());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return new Outcome("error", "interrupted", List.of());
        }
    }

    /** The oracle's virtual environment, made as the harness makes it when it is missing. */
    private static Path environment(Path oracle, Path out) throws IOException, InterruptedException {
        Path venv = oracle.resolve(".venv");
        Path python = venv.resolve("bin").resolve("python");
        if (Files.isExecutable(python) && Files.isDirectory(venv.resolve("lib"))) {
            return python;
        }
        String base = System.getenv().getOrDefault("EMINI_PYTHON", "python3");
        Path log = out.resolve("pymunk-venv.log");
        for (List<String> step : List.of(
                List.of(base, "-m", "venv", venv.toString()),
                List.of(python.toString(), "-m", "pip", "install", "-q", "-r", oracle.resolve("requirements.txt").toString()),
                List.of(python.toString(), "-m", "pip", "install", "-q", "--no-deps", "-e", oracle.toString()))) {
            Process p = new ProcessBuilder(step).redirectErrorStream(true).redirectOutput(log.toFile()).start();
            if (p.waitFor() != 0) {
                throw new IOException(String.join(" ", step) + " failed; see " + log);
            }
        }
        return python;
    }
}
