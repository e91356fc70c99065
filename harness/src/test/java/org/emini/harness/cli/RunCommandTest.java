package org.emini.harness.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import org.emini.harness.Repo;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The command line end to end: exit status, results, JUnit XML and traces. */
class RunCommandTest {
    private static final String FALLING = String.join("\n",
            "bodies: [{name: ball, shape: {type: circle, radius: 5}}]",
            "run:",
            "  duration: 1",
            "  expect:",
            "    - {metric: body.ball.y, of: final, atLeast: 40, %s}",
            "");

    private static int run(Path scenes, Path reports) {
        return run(scenes, reports, Repo.schema());
    }

    private static int run(Path scenes, Path reports, Path schema) {
        return Main.execute("run", "--schema", schema.toString(), "--reports", reports.toString(),
                "--no-progress", scenes.toString());
    }

    private static JsonObject results(Path reports) throws Exception {
        return JsonParser.parseString(Files.readString(reports.resolve("results.json"))).getAsJsonObject();
    }

    @Test
    void passingAndKnownFailuresExitZero(@TempDir Path dir) throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        // Falls 50 px in 1 s (y = ½ g t²): at least 40 holds; at least 60 fails but is marked.
        Files.writeString(scenes.resolve("a-pass.yaml"), String.format(FALLING, "name: falls"));
        Files.writeString(scenes.resolve("b-known.yaml"), String.format(FALLING.replace("atLeast: 40", "atLeast: 60"),
                "knownFailure: {reason: test, measured: 50}"));
        // A key the schema has and the builder does not read (a schema ahead of the harness): unsupported.
        Files.writeString(scenes.resolve("c-unsupported.yaml"), String.join("\n",
                "bodies: [{name: a, shape: {type: circle, radius: 5}}]",
                "particles: [{from: [0, 0], burst: 5}]", "run: {duration: 1}", ""));
        Path reports = dir.resolve("reports");
        assertEquals(0, run(scenes, reports, Repo.schemaAhead(dir)));
        JsonObject summary = results(reports).getAsJsonObject("summary");
        assertEquals(1, summary.get("pass").getAsInt());
        assertEquals(1, summary.get("knownFailure").getAsInt());
        assertEquals(1, summary.get("unsupported").getAsInt());
        assertTrue(Files.readString(reports.resolve("results.json")).contains("$.particles[0].burst"));
        assertTrue(Files.readString(reports.resolve("junit/TEST-scenarios.xml")).contains("tests=\"3\""));
        JsonObject trace = JsonParser.parseString(Files.readString(reports.resolve("traces/a-pass.trace.json")))
                .getAsJsonObject();
        assertEquals("emini-trace", trace.get("format").getAsString());
        assertEquals(21, trace.getAsJsonArray("time").size());
        assertEquals(21, trace.getAsJsonObject("bodies").getAsJsonObject("ball").getAsJsonArray("y").size());
    }

    @Test
    void aRegressionOrAnInvalidSceneExitsNonZero(@TempDir Path dir) throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Files.writeString(scenes.resolve("fail.yaml"), String.format(FALLING.replace("atLeast: 40", "atLeast: 60"),
                "name: too far"));
        assertEquals(1, run(scenes, dir.resolve("r1")));
        assertEquals("FAIL", results(dir.resolve("r1")).getAsJsonArray("scenes").get(0).getAsJsonObject()
                .get("status").getAsString());
        Files.writeString(scenes.resolve("fail.yaml"), "run: {duration: 1, colour: red}\n");
        assertEquals(1, run(scenes, dir.resolve("r2")));
        assertEquals(1, Main.execute("validate", "--schema", Repo.schema().toString(), scenes.toString()));
    }

    @Test
    void aNudgedRunSaysSoAndAFactorOfZeroIsAUsageError(@TempDir Path dir) throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Files.writeString(scenes.resolve("a-pass.yaml"), String.format(FALLING, "name: falls"));
        Path reports = dir.resolve("reports");
        assertEquals(0, Main.execute("run", "--schema", Repo.schema().toString(), "--reports", reports.toString(),
                "--no-progress", "--nudge", "1.02", scenes.toString()));
        assertEquals(1.02, results(reports).get("nudge").getAsDouble());
        assertEquals(1.000002, results(reports).get("nudgeGravity").getAsDouble(), 1e-15);
        assertTrue(Files.readString(reports.resolve("summary.txt")).contains("speculative distance times 1.02 and gravity times 1.000002"));
        assertEquals(2, Main.execute("run", "--schema", Repo.schema().toString(), "--reports",
                dir.resolve("r2").toString(), "--no-progress", "--nudge", "0", scenes.toString()));
    }

    @Test
    void aRunAtTwoWorkersSaysSoAndHasTheSameState(@TempDir Path dir) throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Files.writeString(scenes.resolve("a-pass.yaml"), String.format(FALLING, "name: falls"));
        Path one = dir.resolve("one");
        Path two = dir.resolve("two");
        assertEquals(0, run(scenes, one));
        assertEquals(0, Main.execute("run", "--schema", Repo.schema().toString(), "--reports", two.toString(),
                "--no-progress", "--workers", "2", scenes.toString()));
        assertFalse(results(one).has("workers"), "one worker, as every run before the option");
        assertEquals(2, results(two).get("workers").getAsInt());
        assertTrue(Files.readString(two.resolve("summary.txt")).contains("ticks shared among 2 threads"));
        String hash = results(one).getAsJsonArray("scenes").get(0).getAsJsonObject().get("stateHash").getAsString();
        assertTrue(hash.matches("[0-9a-f]{16}"), hash);
        assertEquals(hash, results(two).getAsJsonArray("scenes").get(0).getAsJsonObject().get("stateHash").getAsString());
        assertEquals(0, Main.execute("diff", "--same-state", one.toString(), two.toString()));
    }

    @Test
    void anOriginalWorldFileRunsAsAScene(@TempDir Path dir) throws Exception {
        Path world = Repo.referenceWorlds().resolve("test_basic.world");
        Path scenes = Files.createDirectories(dir.resolve("worlds"));
        Files.copy(world, scenes.resolve("test_basic.world"));
        // A cut file: the loader names the byte where the reader ran out.
        byte[] bytes = Files.readAllBytes(world);
        Files.write(scenes.resolve("cut.phy"), java.util.Arrays.copyOf(bytes, bytes.length / 2));
        Path reports = dir.resolve("reports");
        assertEquals(1, run(scenes, reports), "the cut file is an error");
        JsonObject r = results(reports);
        assertEquals(1, r.getAsJsonObject("summary").get("pass").getAsInt(), r.toString());
        assertEquals(1, r.getAsJsonObject("summary").get("error").getAsInt(), r.toString());
        String message = r.getAsJsonArray("scenes").get(0).getAsJsonObject().get("message").getAsString();
        assertTrue(message.contains("not a valid world file: byte "), message);
    }
}
