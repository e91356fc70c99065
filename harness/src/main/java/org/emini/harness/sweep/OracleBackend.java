package org.emini.harness.sweep;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.emini.harness.oracle.OracleEnvironment;
import org.emini.harness.oracle.TraceReader;
import org.emini.harness.run.Trace;

/**
 * The pymunk oracle's side of a sweep or stability map. It starts one long-lived
 * {@code python -m emini_oracle serve} process (oracle-py/src/emini_oracle/serve.py) in the oracle's
 * virtual environment, created from the pinned requirements on first use, and sends it every variant
 * as one JSON line; the answer is one JSON line with the trace (format v1, read by {@link TraceReader})
 * and the best wall time of the ticks over the repeats. So Python and pymunk start once per command,
 * not once per point.
 *
 * <p>Timing is the engine side's ({@link EngineBackend}): one run with the metrics gives the trace and
 * warms up, then {@code repeats} timed repeats of the ticks alone (actions, {@code space.step(h)},
 * Emini's damping; no metrics), a short scene run n times per repeat so that a repeat lasts 20 ms;
 * the best of them. The sweep's timestep is pymunk's step and its iteration count
 * pymunk's {@code space.iterations} (oracle-py/MAPPING.md, Sweeps).
 *
 * <p>Statuses: {@code unsupported} (with the reason) when pymunk cannot run the scene or leaves out an
 * element that moves bodies; {@code error} when the variant is invalid, pymunk fails, the process dies
 * (it is started again for the next variant) or a variant takes longer than the time limit. When the
 * environment cannot be set up or the process does not start, {@link #unavailable()} says why and no
 * oracle points are run.
 */
public final class OracleBackend implements SweepBackend, AutoCloseable {
    /** Default time limit for one variant (s). */
    public static final double DEFAULT_TIMEOUT_SECONDS = 600;

    private final OracleEnvironment environment;
    private final Path schema;
    private final Path log;
    private final PrintStream progress;
    private final double timeoutSeconds;
    private final ExecutorService reader = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "oracle-reader");
        t.setDaemon(true);
        return t;
    });

    private final String engine;
    private boolean tried;
    private String unavailable;
    private Process process;
    private BufferedWriter toOracle;
    private BufferedReader fromOracle;
    private String versions = "";
    private long nextId;

    /**
     * @param environment the oracle's virtual environment (created on first use)
     * @param schema the scenario schema the oracle validates variants with
     * @param log where the oracle process's stderr goes (appended)
     * @param progress where environment set-up messages go (stderr)
     * @param timeoutSeconds time limit for one variant
     */
    public OracleBackend(OracleEnvironment environment, Path schema, Path log, PrintStream progress,
                         double timeoutSeconds) {
        this(environment, schema, log, progress, timeoutSeconds, "pymunk");
    }

    /**
     * An oracle backend running one of the oracle's engines.
     *
     * @param environment the oracle's virtual environment (created on first use)
     * @param schema the scenario schema the oracle validates variants with
     * @param log where the oracle process's stderr goes (appended)
     * @param progress where environment set-up messages go (stderr)
     * @param timeoutSeconds time limit for one variant
     * @param engine {@code pymunk} or {@code box2d} (Box2D v3; oracle-py/MAPPING.md, Box2D v3)
     */
    public OracleBackend(OracleEnvironment environment, Path schema, Path log, PrintStream progress,
                         double timeoutSeconds, String engine) {
        this.engine = engine;
        this.environment = environment;
        this.schema = schema.toAbsolutePath();
        this.log = log.toAbsolutePath();
        this.progress = progress;
        this.timeoutSeconds = timeoutSeconds;
    }

    @Override
    public String name() {
        return engine;
    }

    /** Sets up the environment and starts the oracle on first call; null when it runs, else why not. */
    @Override
    public synchronized String unavailable() {
        if (!tried) {
            tried = true;
            try {
                start();
            } catch (IOException e) {
                unavailable = "the " + engine + " oracle cannot run: " + e.getMessage().strip()
                        + " (the environment is oracle-py/.venv, built from oracle-py/requirements.txt;"
                        + " set EMINI_PYTHON or --python to choose the interpreter)";
                stop();
            }
        }
        return unavailable;
    }

    /** pymunk's and Chipmunk's versions as the running oracle reports them, or "". */
    public synchronized String versions() {
        return versions;
    }

    @Override
    public synchronized Measured run(String sceneId, String variantText, int repeats) {
        if (unavailable() != null) {
            return new Measured("unsupported", unavailable, null, Double.NaN, Double.NaN);
        }
        try {
            if (process == null || !process.isAlive()) {
                start();
            }
        } catch (IOException e) {
            return new Measured("error", "the oracle did not start again: " + e.getMessage(), null, Double.NaN, Double.NaN);
        }
        long id = nextId++;
        JsonObject request = new JsonObject();
        request.addProperty("id", id);
        request.addProperty("scene", sceneId);
        request.addProperty("text", variantText);
        request.addProperty("repeats", Math.max(0, repeats));
        String line;
        try {
            toOracle.write(request.toString());
            toOracle.write('\n');
            toOracle.flush();
            line = readLine(timeoutSeconds);
        } catch (TimeoutException e) {
            stop();
            return new Measured("error", "the oracle took longer than " + (long) timeoutSeconds + " s on this variant"
                    + " (stopped; it starts again for the next)", null, Double.NaN, Double.NaN);
        } catch (IOException e) {
            line = null;
        }
        if (line == null) {
            String why = died();
            stop();
            return new Measured("error", why, null, Double.NaN, Double.NaN);
        }
        return parse(line, id);
    }

    private Measured parse(String line, long id) {
        JsonObject r;
        try {
            r = JsonParser.parseString(line).getAsJsonObject();
        } catch (RuntimeException e) {
            return new Measured("error", "the oracle answered something that is not JSON: " + abbreviate(line), null,
                    Double.NaN, Double.NaN);
        }
        if (!r.has("id") || r.get("id").isJsonNull() || r.get("id").getAsLong() != id) {
            stop(); // out of step: start afresh
            return new Measured("error", "the oracle answered another request: " + abbreviate(line), null,
                    Double.NaN, Double.NaN);
        }
        String status = text(r, "status");
        String message = text(r, "message");
        double simulated = number(r, "simulatedSeconds");
        if (!status.equals("ok")) {
            return new Measured(status.equals("unsupported") ? "unsupported" : "error", message, null, Double.NaN, simulated);
        }
        Trace trace;
        try {
            trace = TraceReader.parse(r.getAsJsonObject("trace"), "pymunk trace of " + text(r, "scene")).trace();
        } catch (IOException | RuntimeException e) {
            return new Measured("error", "unreadable oracle trace: " + e.getMessage(), null, Double.NaN, simulated);
        }
        return new Measured("ok", notes(r), trace, number(r, "stepSeconds"), simulated, number(r, "stepCpuSeconds"));
    }

    /** What pymunk runs differently or leaves out (without changing the bodies' motion), for an ok point. */
    private static String notes(JsonObject r) {
        List<String> out = new ArrayList<>();
        for (String list : List.of("approximations", "unsupported")) {
            if (r.has(list) && r.get(list).isJsonArray()) {
                for (JsonElement e : r.getAsJsonArray(list)) {
                    JsonObject n = e.getAsJsonObject();
                    out.add((list.equals("unsupported") ? "left out: " : "approximated: ") + text(n, "element"));
                }
            }
        }
        return String.join("; ", out);
    }

    private void start() throws IOException {
        stop();
        Path interpreter = environment.ensure(progress);
        Files.createDirectories(log.getParent());
        List<String> command = List.of(interpreter.toString(), "-m", "emini_oracle", "serve", "--engine", engine,
                "--schema", schema.toString());
        process = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.appendTo(log.toFile()))
                .redirectInput(ProcessBuilder.Redirect.PIPE).start();
        toOracle = new BufferedWriter(new OutputStreamWriter(process.getOutputStream(), StandardCharsets.UTF_8));
        fromOracle = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        String ready;
        try {
            ready = readLine(120);
        } catch (TimeoutException e) {
            stop();
            throw new IOException("the oracle process did not answer within 120 s: " + String.join(" ", command));
        }
        if (ready == null) {
            String why = died();
            stop();
            throw new IOException(why);
        }
        try {
            JsonObject r = JsonParser.parseString(ready).getAsJsonObject();
            if (!r.has("ready") || !r.get("ready").getAsBoolean()) {
                throw new IllegalStateException("no ready line");
            }
            versions = engine.equals("box2d") ? "Box2D " + text(r, "box2d") + " (pyb2d3 " + text(r, "pyb2d3") + ")"
                    : "pymunk " + text(r, "pymunk") + ", Chipmunk " + text(r, "chipmunk");
        } catch (RuntimeException e) {
            stop();
            throw new IOException("the oracle process did not start as expected; it said: " + abbreviate(ready));
        }
    }

    private String readLine(double seconds) throws IOException, TimeoutException {
        BufferedReader in = fromOracle;
        Future<String> f = reader.submit(in::readLine);
        try {
            return f.get((long) Math.ceil(seconds * 1000), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            f.cancel(true);
            throw new IOException("interrupted", e);
        } catch (ExecutionException e) {
            throw e.getCause() instanceof IOException io ? io : new IOException(e.getCause());
        } catch (TimeoutException e) {
            f.cancel(true);
            throw e;
        }
    }

    /** Why the process ended: its exit status and the end of its log. */
    private String died() {
        String status = "";
        if (process != null) {
            try {
                if (process.waitFor(5, TimeUnit.SECONDS)) {
                    status = " (exit " + process.exitValue() + ")";
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        return "the oracle process ended" + status + " on this variant; the end of " + log.getFileName() + ": "
                + tail(log, 600);
    }

    static String tail(Path file, int chars) {
        try {
            String s = Files.readString(file, StandardCharsets.UTF_8).strip();
            return s.length() <= chars ? s : "..." + s.substring(s.length() - chars);
        } catch (IOException e) {
            return "(no log)";
        }
    }

    private void stop() {
        if (process != null) {
            try {
                toOracle.close();
            } catch (IOException e) {
                // the process is gone
            }
            process.destroy();
            try {
                if (!process.waitFor(5, TimeUnit.SECONDS)) {
                    process.destroyForcibly();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                process.destroyForcibly();
            }
            process = null;
        }
    }

    /** Ends the oracle process (it exits when its input closes). */
    @Override
    public synchronized void close() {
        if (process != null) {
            try {
                toOracle.close();
                if (!process.waitFor(10, TimeUnit.SECONDS)) {
                    process.destroyForcibly();
                }
            } catch (IOException e) {
                process.destroyForcibly();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                process.destroyForcibly();
            }
            process = null;
        }
        reader.shutdownNow();
    }

    private static String abbreviate(String s) {
        return s.length() <= 300 ? s : s.substring(0, 300) + "...";
    }

    private static String text(JsonObject o, String key) {
        JsonElement e = o.get(key);
        return e == null || e.isJsonNull() ? "" : e.getAsString();
    }

    private static double number(JsonObject o, String key) {
        JsonElement e = o.get(key);
        return e == null || e.isJsonNull() ? Double.NaN : e.getAsDouble();
    }

    /** A backend for a command: the environment beside the scenario library unless given. */
    public static OracleBackend forLibrary(Path oracleHome, String python, Path schema, Path log) {
        return new OracleBackend(new OracleEnvironment(oracleHome, python), schema, log, System.err,
                DEFAULT_TIMEOUT_SECONDS);
    }
}
