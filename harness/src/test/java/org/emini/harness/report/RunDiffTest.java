package org.emini.harness.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** diff: an error against the truth or a CPU time that grew beyond its tolerance is a regression; noise is not. */
class RunDiffTest {
    private static final RunDiff.Tolerances TOL = new RunDiff.Tolerances(0.1, 0.25, 1, 200);

    private static Path run(Path dir, double error, double tolerance, double cpuMs) throws IOException {
        Files.createDirectories(dir.resolve("compare"));
        Files.createDirectories(dir.resolve("bench"));
        Files.writeString(dir.resolve("compare/compare.json"), """
                {"format": "emini-compare", "scenes": [{"scene": "closed-form/pendulum", "rows": [
                  {"channel": "body.bob.x", "figure": "series, maxError", "referenceSource": "closed form pendulum",
                   "engineError": %s, "tolerance": %s},
                  {"channel": "body.bob.vx", "figure": "series", "referenceSource": null, "engineError": null, "tolerance": 1}]}]}
                """.formatted(error, tolerance));
        Files.writeString(dir.resolve("bench/bench.json"), """
                {"format": "emini-bench", "scenes": [{"id": "bench/pyramid-20", "results": [
                  {"engine": "emini", "cpuMsPerTick": %s}, {"engine": "dyn4j", "cpuMsPerTick": 0.9}]}]}
                """.formatted(cpuMs));
        return dir;
    }

    @Test
    void aGrownErrorAndASlowerTickAreRegressions(@TempDir Path tmp) throws IOException {
        Path old = run(tmp.resolve("old"), 0.20, 1, 0.40);
        RunDiff.Result same = RunDiff.diff(old, run(tmp.resolve("noise"), 0.21, 1, 0.45), TOL);
        assertEquals(List.of(), same.changes(), "5% more error and 12% more time are within the tolerances");
        assertEquals(1, same.compared().get("accuracy"), "rows without a reference are not compared");
        assertEquals(2, same.compared().get("speed"));

        RunDiff.Result worse = RunDiff.diff(old, run(tmp.resolve("worse"), 0.30, 1, 0.60), TOL);
        assertEquals(2, worse.regressions().size(), worse.changes().toString());
        RunDiff.Change acc = worse.regressions().get(0);
        assertEquals("accuracy", acc.kind());
        assertEquals("closed-form/pendulum", acc.scene());
        assertTrue(acc.what().startsWith("body.bob.x"), acc.what());
        assertEquals("emini CPU ms/tick", worse.regressions().get(1).what());

        RunDiff.Result better = RunDiff.diff(tmp.resolve("worse"), old, TOL);
        assertEquals(0, better.regressions().size());
        assertEquals(2, better.changes().size(), "the way back is two improvements");
    }

    @Test
    void aFigureLostToNaNIsARegressionAndTinyErrorsAreNoise(@TempDir Path tmp) throws IOException {
        Path old = run(tmp.resolve("old"), 1e-7, 1, 0.4);
        assertEquals(List.of(), RunDiff.diff(old, run(tmp.resolve("tiny"), 3e-7, 1, 0.4), TOL).changes(),
                "below a hundredth of the row's tolerance an error is float noise");
        assertEquals(1, RunDiff.diff(old, run(tmp.resolve("nan"), Double.NaN, 1, 0.4), TOL).regressions().size());
    }

    /** A results.json of scenes, each "id" or "id=hash" (a scene without a hash ran into an error). */
    private static Path results(Path dir, String... scenes) throws IOException {
        StringBuilder json = new StringBuilder("{\"format\": \"emini-results\", \"scenes\": [");
        for (int i = 0; i < scenes.length; i++) {
            String[] s = scenes[i].split("=");
            json.append(i == 0 ? "" : ", ").append("{\"scene\": \"").append(s[0]).append("\", \"status\": \"")
                    .append(s.length > 1 ? "pass\", \"stateHash\": \"" + s[1] : "ERROR").append("\"}");
        }
        Files.createDirectories(dir);
        Files.writeString(dir.resolve("results.json"), json.append("]}"));
        return dir;
    }

    @Test
    void aDifferentStateIsARegressionOfSameStateAndAMissingOneANote(@TempDir Path tmp) throws IOException {
        Path old = results(tmp.resolve("old"), "a=00000000000000a1", "b=00000000000000b1", "c", "d=00000000000000d1");
        Path now = results(tmp.resolve("new"), "a=00000000000000a1", "b=00000000000000b2", "c=00000000000000c2",
                "e=00000000000000e2");
        RunDiff.Result r = RunDiff.sameState(old, now);
        assertEquals(List.of(new RunDiff.Change("state", "b", "stateHash", "00000000000000b1", "00000000000000b2", true)),
                r.changes());
        assertEquals(2, r.compared().get("state hashes"), "a and b: in both, with a hash in both");
        assertEquals(List.of("1 of 2 scenes with a state hash in both have the same state",
                "1 scenes of OLD not in NEW: d", "1 scenes of NEW not in OLD: e",
                "1 scenes without a state hash in OLD or NEW (unsupported, or stopped by an error): c"), r.notes());
        assertEquals(List.of(), RunDiff.sameState(old, old).changes());

        RunDiff.Result plain = RunDiff.diff(old, now, TOL);
        assertEquals(List.of(), plain.regressions(), "without --same-state a state is no regression");
        assertTrue(plain.notes().contains("1 of 2 scenes with a state hash in both have the same state (bit for bit; "
                + "diff --same-state fails on the others)"), plain.notes().toString());

        Path unhashed = results(tmp.resolve("unhashed"), "a", "b");
        assertTrue(RunDiff.sameState(old, unhashed).compared().isEmpty(), "nothing to compare: a usage error");
    }

    @Test
    void aFolderWithoutResultsOrAForeignFileIsAnError(@TempDir Path tmp) throws IOException {
        Files.createDirectories(tmp.resolve("empty"));
        IOException x = assertThrows(IOException.class, () -> RunDiff.diff(tmp.resolve("empty"), tmp.resolve("empty"), TOL));
        assertTrue(x.getMessage().contains("holds no results.json"), x.getMessage());
        Files.writeString(tmp.resolve("x.json"), "{\"format\": \"emini-trace\"}");
        x = assertThrows(IOException.class, () -> RunDiff.diff(tmp.resolve("x.json"), tmp.resolve("x.json"), TOL));
        assertTrue(x.getMessage().contains("not a harness results"), x.getMessage());
    }
}
