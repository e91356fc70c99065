package org.emini.harness.dashboard;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import com.google.gson.JsonArray;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The dashboard's nudged runs: every reports/nudged/* run that says its factor, smallest first. */
class NudgedRunsTest {
    private static void results(Path dir, String nudge, String status) throws IOException {
        Files.createDirectories(dir);
        Files.writeString(dir.resolve("results.json"), "{\"generated\": \"now\"" + (nudge == null ? "" : ", \"nudge\": " + nudge)
                + ", \"summary\": {\"scenes\": 1}, \"scenes\": [{\"scene\": \"bench/pyramid-100\", \"status\": \"" + status
                + "\", \"message\": \"m\"}]}");
    }

    @Test
    void theRunsAreReadSmallestFactorFirstAndARunWithoutAFactorIsLeftOut(@TempDir Path reports) throws IOException {
        Path nudged = reports.resolve("nudged");
        results(nudged.resolve("x1.02"), "1.02", "FAIL");
        results(nudged.resolve("x0.98"), "0.98", "pass");
        results(nudged.resolve("plain"), null, "pass");
        Files.createDirectories(nudged.resolve("empty"));
        JsonArray runs = DashboardWriter.nudgedRuns(nudged);
        assertEquals(2, runs.size());
        assertEquals(0.98, runs.get(0).getAsJsonObject().get("nudge").getAsDouble());
        assertEquals(1.02, runs.get(1).getAsJsonObject().get("nudge").getAsDouble());
        assertEquals("FAIL", runs.get(1).getAsJsonObject().getAsJsonArray("scenes").get(0).getAsJsonObject().get("status").getAsString());
    }

    @Test
    void noFolderOrNoNudgedRunIsNone(@TempDir Path reports) throws IOException {
        assertNull(DashboardWriter.nudgedRuns(reports.resolve("nudged")));
        results(reports.resolve("nudged").resolve("plain"), null, "pass");
        assertNull(DashboardWriter.nudgedRuns(reports.resolve("nudged")));
    }
}
