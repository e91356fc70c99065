package org.emini.harness.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.ExecutionException;
import org.emini.harness.Repo;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * A user's mistake or a failing disk gets one clear line and a documented status (harness/README.md,
 * Exit status); issue 14 found stack traces, and --jobs 0 and empty folders accepted.
 */
class ExitStatusTest {
    private record Outcome(int status, String err) {
    }

    private static Outcome run(String... args) {
        PrintStream saved = System.err;
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            int status = Main.execute(args);
            return new Outcome(status, err.toString(StandardCharsets.UTF_8));
        } finally {
            System.setErr(saved);
        }
    }

    private static void oneLine(Outcome o) {
        assertFalse(o.err().contains("\tat "), "no stack trace: " + o.err());
        assertTrue(o.err().lines().count() <= 2, o.err());
    }

    private static Path scene(Path dir) throws Exception {
        Path file = dir.resolve("s.yaml");
        Files.writeString(file, "bodies: [{shape: {type: circle, radius: 5}}]\nrun: {duration: 0.1}\n");
        return file;
    }

    @Test
    void reportsUnderAFileIsAnInputOutputErrorInOneLine(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("plain"), "x");
        Outcome o = run("run", "--schema", Repo.schema().toString(), "--reports", file.resolve("r").toString(),
                "--no-progress", scene(dir).toString());
        assertEquals(ExitStatus.IO, o.status(), o.err());
        assertTrue(o.err().contains(file.resolve("r").toString()), o.err());
        oneLine(o);
    }

    /** {@code run} with one option's value: a usage error whose one line says what is wrong. */
    private static void refused(Path dir, String option, String value, String message) throws Exception {
        Outcome o = run("run", "--schema", Repo.schema().toString(), "--reports", dir.resolve("r").toString(),
                option, value, scene(dir).toString());
        assertEquals(ExitStatus.USAGE, o.status(), option + " " + value);
        assertTrue(o.err().contains(message), o.err());
        oneLine(o);
    }

    @Test
    void jobsMustBePositive(@TempDir Path dir) throws Exception {
        for (String jobs : new String[] {"0", "-3"}) {
            refused(dir, "--jobs", jobs, "--jobs must be at least 1, was " + jobs);
        }
    }

    @Test
    void workersMustBeOneToSixtyFour(@TempDir Path dir) throws Exception {
        for (String workers : new String[] {"0", "65"}) {
            refused(dir, "--workers", workers, "--workers must be 1 to 64, was " + workers);
        }
    }

    @Test
    void aFolderWithoutScenesIsAUsageError(@TempDir Path dir) throws Exception {
        Path empty = Files.createDirectories(dir.resolve("empty"));
        for (String command : new String[] {"validate", "run", "expand"}) {
            Outcome o = run(command, "--schema", Repo.schema().toString(), empty.toString());
            assertEquals(ExitStatus.USAGE, o.status(), command);
            assertTrue(o.err().contains("no scene files in " + empty), o.err());
        }
    }

    @Test
    void convertingAMissingFileSaysItIsMissing(@TempDir Path dir) {
        Outcome o = run("convert", dir.resolve("nope.phy").toString());
        assertEquals(ExitStatus.IO, o.status());
        assertTrue(o.err().contains("nope.phy: no such file"), o.err());
        oneLine(o);
    }

    @Test
    void badRatesAreUsageErrorsNotAnEndlessLoop() {
        Outcome o = run("stability", "--rates", "1..2147483647", "--engines", "emini");
        assertEquals(ExitStatus.USAGE, o.status(), o.err());
        assertEquals(ExitStatus.USAGE, run("stability", "--families", "nope", "--engines", "emini").status());
    }

    /** An OutOfMemoryError, even one a worker thread met, is one line with its own status. */
    @Test
    void outOfMemoryIsOneLine() {
        CommandLine cmd = new CommandLine(new Main());
        StringWriter text = new StringWriter();
        cmd.setErr(new PrintWriter(text, true));
        Throwable wrapped = new IllegalStateException(new ExecutionException(new OutOfMemoryError("Java heap space")));
        assertEquals(ExitStatus.OUT_OF_MEMORY, Failures.report(wrapped, cmd));
        assertTrue(text.toString().contains("out of memory (Java heap space)"), text.toString());
        assertEquals(1, text.toString().lines().count(), text.toString());
    }

    @Test
    void anUnexpectedExceptionIsNamedAsADefectInOneLine() {
        CommandLine cmd = new CommandLine(new Main());
        StringWriter text = new StringWriter();
        cmd.setErr(new PrintWriter(text, true));
        assertEquals(ExitStatus.INTERNAL, Failures.report(new NullPointerException("x"), cmd));
        assertTrue(text.toString().contains("internal error: java.lang.NullPointerException: x"), text.toString());
        assertEquals(1, text.toString().lines().count(), text.toString());
    }
}
