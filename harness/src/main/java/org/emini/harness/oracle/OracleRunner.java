package org.emini.harness.oracle;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Runs scenes in the oracle: one {@code python -m emini_oracle run} process for all of them, which
 * writes a trace per scene and {@code oracle-results.json} into the output folder.
 */
public final class OracleRunner {
    private final Path interpreter;
    private final Path schema;

    /**
     * @param interpreter the oracle environment's Python
     * @param schema the scenario schema (scene ids are relative to its folder, as in the harness)
     */
    public OracleRunner(Path interpreter, Path schema) {
        this.interpreter = interpreter;
        this.schema = schema;
    }

    /** A started oracle run; {@link #await()} waits for it and reads what it wrote. */
    public final class Run {
        private final Process process;
        private final Path out;
        private final Path log;

        private Run(Process process, Path out, Path log) {
            this.process = process;
            this.out = out;
            this.log = log;
        }

        /**
         * Waits for the oracle and reads its results.
         *
         * @return what the oracle said per scene, by scene file (absolute, normalised)
         * @throws IOException if the oracle process failed before writing its results
         */
        public Map<Path, OracleScene> await() throws IOException, InterruptedException {
            int status = process.waitFor();
            Path results = out.resolve("oracle-results.json");
            if (!Files.isRegularFile(results)) {
                throw new IOException("the oracle exited with status " + status + " and wrote no results:\n"
                        + Files.readString(log, StandardCharsets.UTF_8));
            }
            return read(results);
        }
    }

    /**
     * Starts the oracle on scene files.
     *
     * @param files the scene files
     * @param out where traces and oracle-results.json go
     * @param jobs scenes the oracle runs in parallel
     */
    public Run start(List<Path> files, Path out, int jobs) throws IOException {
        return start(files, out, jobs, "pymunk");
    }

    /**
     * Starts one of the oracle's engines on scene files.
     *
     * @param files the scene files
     * @param out where traces and oracle-results.json go
     * @param jobs scenes the oracle runs in parallel
     * @param engine {@code pymunk} or {@code box2d}
     */
    public Run start(List<Path> files, Path out, int jobs, String engine) throws IOException {
        Files.createDirectories(out);
        Files.deleteIfExists(out.resolve("oracle-results.json"));
        List<String> command = new ArrayList<>(List.of(interpreter.toString(), "-m", "emini_oracle", "run",
                "--engine", engine, "--quiet", "--schema", schema.toAbsolutePath().toString(), "--jobs", Integer.toString(jobs),
                "--out", out.toAbsolutePath().toString()));
        for (Path f : files) {
            command.add(f.toAbsolutePath().toString());
        }
        Path log = out.resolve("oracle.log");
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null"))).start();
        return new Run(p, out, log);
    }

    /** Reads oracle-results.json. */
    static Map<Path, OracleScene> read(Path results) throws IOException {
        JsonObject doc = JsonParser.parseString(Files.readString(results, StandardCharsets.UTF_8)).getAsJsonObject();
        Map<Path, OracleScene> out = new LinkedHashMap<>();
        for (JsonElement e : doc.getAsJsonArray("scenes")) {
            JsonObject s = e.getAsJsonObject();
            OracleScene scene = new OracleScene(s.get("file").getAsString(), text(s, "scene"),
                    s.get("status").getAsString(), text(s, "message"), notes(s.getAsJsonArray("unsupported")),
                    notes(s.getAsJsonArray("approximations")), text(s, "trace"));
            out.put(Path.of(scene.file()).toAbsolutePath().normalize(), scene);
        }
        return out;
    }

    private static List<OracleScene.Note> notes(JsonArray list) {
        List<OracleScene.Note> out = new ArrayList<>();
        if (list != null) {
            for (JsonElement e : list) {
                JsonObject n = e.getAsJsonObject();
                out.add(new OracleScene.Note(n.get("element").getAsString(), n.get("path").getAsString(),
                        n.get("reason").getAsString(), n.get("affectsBodies").getAsBoolean()));
            }
        }
        return out;
    }

    private static String text(JsonObject o, String key) {
        JsonElement e = o.get(key);
        return e == null || e.isJsonNull() ? null : e.getAsString();
    }
}
