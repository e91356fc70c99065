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
