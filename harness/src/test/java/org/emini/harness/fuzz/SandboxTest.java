package org.emini.harness.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import org.emini.harness.Repo;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The worker process is the fuzzer's safety: a hang is answered with where it was stuck and the worker
 * replaced, a death or an OutOfMemoryError is a crash, and the next input gets a fresh worker.
 */
class SandboxTest {
    @Test
    void hangsDeathsAndOutOfMemoryAreClassifiedAndTheRunGoesOn(@TempDir Path dir) throws Exception {
        try (Sandbox s = new Sandbox(MisbehavingChecker.class.getName(), Repo.schema(), 1, "64m", Duration.ofSeconds(3),
                dir.resolve("worker.log"))) {
            assertEquals(Outcome.CLEAN, run(s, "first").outcome());
            Verdict hang = run(s, "hang");
            assertEquals(Outcome.HANG, hang.outcome());
            // The worker names where its check was stuck, and so whose the hang is.
            assertTrue(hang.message().contains("MisbehavingChecker.check"), hang.message());
            assertEquals(Verdict.HARNESS, hang.blame());
            assertEquals(Outcome.CLEAN, run(s, "after a hang").outcome());
            Verdict died = run(s, "die");
            assertEquals(Outcome.CRASH, died.outcome());
            assertTrue(died.message().contains("exit status 7"), died.message());
            assertEquals(Outcome.CLEAN, run(s, "after a death").outcome());
            Verdict oom = run(s, "oom");
            assertEquals(Outcome.CRASH, oom.outcome());
            assertTrue(oom.message().startsWith("java.lang.OutOfMemoryError"), oom.message());
            Verdict last = run(s, "after running out of memory");
            assertEquals(Outcome.CLEAN, last.outcome());
            assertEquals("after running out of memory", last.message());
        }
    }

    private static Verdict run(Sandbox s, String input) throws Exception {
        return s.run(input.getBytes(StandardCharsets.UTF_8));
    }
}
