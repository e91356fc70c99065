package org.emini.harness.fuzz;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * Runs inputs in a {@link FuzzWorker} process: a time limit per input (a hang is killed and the worker
 * started again) and a bounded heap. One worker serves many inputs, so the JVM starts rarely.
 */
final class Sandbox implements AutoCloseable {
    private static final String EOF = "\u0000eof";
    private static final Duration STARTUP = Duration.ofSeconds(120);
    private static final Duration BACKSTOP = Duration.ofSeconds(30);

    private final List<String> command;
    private final Duration timeout;
    private final Path log;
    private Process process;
    private Writer toWorker;
    private BlockingQueue<String> answers;

    /**
     * @param target the worker's target
     * @param schema the scenario schema
     * @param ticks ticks per accepted input
     * @param heap the worker's -Xmx (such as 512m)
     * @param timeout the time limit per input
     * @param log where the worker's stderr goes
     */
    Sandbox(String target, Path schema, int ticks, String heap, Duration timeout, Path log) {
        this.command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + heap, "-XX:+UseSerialGC", "-cp", System.getProperty("java.class.path"),
                FuzzWorker.class.getName(), target, schema.toAbsolutePath().toString(), Integer.toString(ticks),
                Long.toString(timeout.toSeconds())));
        this.timeout = timeout;
        this.log = log;
    }

    /** The verdict on one input: the worker's, or a hang (killed) or a crash (the worker died). */
    Verdict run(byte[] input) throws IOException, InterruptedException {
        if (process == null || !process.isAlive()) {
            start();
        }
        toWorker.write(Base64.getEncoder().encodeToString(input));
        toWorker.write('\n');
        toWorker.flush();
        // The worker answers a hang itself at the limit; this backstop is for a worker too far gone to.
        String line = answers.poll(timeout.plus(BACKSTOP).toMillis(), TimeUnit.MILLISECONDS);
        if (line == null) {
            stop();
            return new Verdict(Outcome.HANG, "", "worker", "no answer within " + timeout.toSeconds() + " s; killed");
        }
        if (line.equals(EOF)) {
            int status = process.waitFor();
            process = null;
            return new Verdict(Outcome.CRASH, Verdict.HARNESS, "worker", "the worker died (exit status " + status
                    + "); see " + log);
        }
        Verdict v = Verdict.decode(line);
        if (FuzzWorker.fatal(v) || v.outcome() == Outcome.HANG) {
            process.waitFor(30, TimeUnit.SECONDS);
            stop();
        }
        return v;
    }

    private void start() throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.appendTo(log.toFile()));
        process = pb.start();
        toWorker = new OutputStreamWriter(process.getOutputStream(), StandardCharsets.US_ASCII);
        BlockingQueue<String> queue = new LinkedBlockingQueue<>();
        answers = queue;
        BufferedReader from = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        Thread reader = new Thread(() -> {
            try {
                for (String l; (l = from.readLine()) != null;) {
                    queue.add(l);
                }
            } catch (IOException e) {
                // The worker was killed: same as its end.
            }
            queue.add(EOF);
        }, "fuzz-worker-answers");
        reader.setDaemon(true);
        reader.start();
        String ready = queue.poll(STARTUP.toMillis(), TimeUnit.MILLISECONDS);
        if (!"ready".equals(ready)) {
            stop();
            throw new IOException("the fuzz worker did not start (" + ready + "); see " + log);
        }
    }

    private void stop() throws InterruptedException {
        if (process != null) {
            process.destroyForcibly();
            process.waitFor(30, TimeUnit.SECONDS);
            process = null;
        }
    }

    @Override
    public void close() {
        try {
            stop();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
