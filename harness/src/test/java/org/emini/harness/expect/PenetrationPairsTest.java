package org.emini.harness.expect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.emini.harness.Scenes;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.metrics.PenetrationPair;
import org.emini.harness.oracle.TraceReader;
import org.emini.harness.report.ConsoleTable;
import org.emini.harness.report.ResultsWriter;
import org.emini.harness.report.Summary;
import org.emini.harness.report.TraceWriter;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.Trace;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Penetration per pair of bodies, named: the run's deepest pairs (results, trace, console line) and
 * {@code between: [A, B]}, the penetration channels narrowed to the pairs of two bodies or groups.
 */
class PenetrationPairsTest {
    /**
     * A ball starts 6 px deep in a static ground (pushed out over a few ticks at 20 ticks/s and 2
     * iterations), another is put down on a landscape segment far away, and a row of three balls rests on a
     * second ground.
     */
    private static final String SCENE = String.join("\n",
            "world: {ticksPerSecond: 20, iterations: 2}",
            "shapes: {ball: {type: circle, radius: 10}, ground: {type: rectangle, width: 200, height: 20}}",
            "bodies:",
            "  - {name: ground, shape: ground, position: [0, 10], static: true}",
            "  - {name: sunk, shape: ball, position: [0, -4]}",
            "  - {name: slow, shape: ball, position: [1000, -10.5]}",
            "  - {name: shelf, shape: ground, position: [-1000, 10], static: true}",
            "generators: [{type: row, name: pebble, shape: ball, start: [-1040, -10.5], count: 3, spacing: [40, 0]}]",
            "landscape: {segments: [{from: [900, 0], to: [1100, 0]}]}",
            "run:",
            "  duration: 1",
            "  record: {metrics: [penetration]}",
            "  expect:");

    private static SceneResult run(String... expect) {
        return ScenarioRunner.run(Scenes.valid("pairs.yaml", SCENE + "\n" + String.join("\n", expect)), n -> { });
    }

    private static double max(double[] v) {
        double m = 0;
        for (double x : v) {
            m = Math.max(m, x);
        }
        return m;
    }

    @Test
    void theDeepestPairsAreNamedAndTheWorstIsTheWorldsDeepestOverlap() {
        SceneResult r = run("    - {metric: penetration.max, of: max, atLeast: 0}");
        List<PenetrationPair> pairs = r.trace().penetrationPairs();
        // sunk-ground, slow-landscape and the three pebbles on the shelf; the balls never meet each other.
        assertEquals(5, pairs.size(), pairs.toString());
        PenetrationPair worst = pairs.get(0);
        assertEquals("ground", worst.a());
        assertEquals("sunk", worst.b());
        // Sampled every tick: the deepest pair's max is the world's penetration.max over the run, exactly.
        assertEquals(max(r.trace().column("penetration.max")), worst.max(), 0);
        assertTrue(worst.max() > 1, "started 6 px deep, pushed out over ticks: " + worst.max());
        assertTrue(pairs.stream().anyMatch(p -> p.a().equals("slow") && p.b().equals("landscape")), pairs.toString());
        assertTrue(pairs.stream().anyMatch(p -> p.a().equals("shelf") && p.b().equals("pebble[1]")), pairs.toString());
        for (PenetrationPair p : pairs) {
            assertTrue(p.mean() > 0 && p.mean() <= p.max() && p.samples() > 0, p.toString());
        }
        // The result keeps the deepest ones; the console line names the worst.
        assertEquals(pairs.subList(0, SceneResult.TOP_PAIRS), r.penetrationPairs());
        assertTrue(ConsoleTable.line(r, 10).contains("deepest overlap ground–sunk"), ConsoleTable.line(r, 10));
    }

    @Test
    void betweenBoundsOnePairAndFailsForTheDeepOne() {
        SceneResult r = run(
                "    - {metric: penetration.max, between: [slow, landscape], of: max, atMost: 0.5}",
                "    - {metric: penetration.max, between: [sunk, ground], of: max, atMost: 0.5}",
                "    - {metric: penetration.max, between: [sunk, slow], of: max, atMost: 0}",
                // A bare generator name is the generator's bodies: the three pebbles on the shelf.
                "    - {metric: penetration.max, between: [pebble, shelf], of: max, atMost: 0.5}",
                "    - {metric: penetration.points, between: ['*', landscape], of: max, atLeast: 1}");
        assertTrue(r.verdicts().get(0).passed(), r.verdicts().get(0).detail());
        assertFalse(r.verdicts().get(1).passed(), "the deep pair must fail: " + r.verdicts().get(1).detail());
        double sunkGround = r.penetrationPairs().get(0).max();
        assertEquals(sunkGround, r.verdicts().get(1).measured(), 0);
        assertTrue(r.verdicts().get(2).passed(), "sunk and slow never touch: " + r.verdicts().get(2).detail());
        assertEquals(0, r.verdicts().get(2).measured(), 0);
        assertTrue(r.verdicts().get(3).passed(), r.verdicts().get(3).detail());
        double pebbles = r.trace().penetrationPairs().stream().filter(p -> p.b().startsWith("pebble["))
                .mapToDouble(PenetrationPair::max).max().orElseThrow();
        assertEquals(pebbles, r.verdicts().get(3).measured(), 0);
        assertTrue(pebbles > 0, "resting pebbles overlap a little");
        assertTrue(r.verdicts().get(4).passed(), r.verdicts().get(4).detail());
        // The channels are in the trace, named by the pair filter as read.
        assertTrue(r.trace().metricChannels().contains("penetration.max(pebble[*], shelf)"), r.trace().metricChannels().toString());
        assertTrue(r.verdicts().get(3).expectation().startsWith("penetration.max(pebble[*], shelf) max"),
                r.verdicts().get(3).expectation());
    }

    @Test
    void pairsGoToTheTraceFileAndResultsAndComeBack(@TempDir Path dir) throws Exception {
        SceneResult r = run("    - {metric: penetration.max, between: [sunk, ground], of: max, atLeast: 0}");
        Path file = dir.resolve("pairs.trace.json");
        TraceWriter.write(file, "pairs", "emini", r.trace());
        Trace back = TraceReader.read(file).trace();
        assertEquals(r.trace().penetrationPairs(), back.penetrationPairs());
        assertTrue(back.has("penetration.max(sunk, ground)"));
        Path results = dir.resolve("results.json");
        ResultsWriter.write(results, List.of(r), Summary.of(List.of(r), 1), null);
        String json = Files.readString(results);
        assertTrue(json.contains("\"penetrationPairs\"") && json.contains("\"a\": \"ground\"")
                && json.contains("\"b\": \"sunk\""), json);
        StringWriter none = new StringWriter();
        TraceWriter.write(none, "x", "emini", new Trace(0.1, List.of(), List.of()));
        assertFalse(none.toString().contains("penetrationPairs"), "a run without penetration writes no pairs");
    }

    @Test
    void betweenNamesWhatItCannotReadWhereItIsWritten() {
        ScenarioLoader.Loaded l = Scenes.load("bad.yaml", SCENE, "    - {metric: energy.total, between: [sunk, ground], of: max, atMost: 1}");
        assertTrue(Scenes.onlyProblem(l).message().startsWith("between narrows penetration.max"), Scenes.onlyProblem(l).message());
        assertEquals("$.run.expect[0].between", Scenes.onlyProblem(l).path());
        l = Scenes.load("bad.yaml", SCENE, "    - {metric: penetration.max, between: [sunk, nobody], of: max, atMost: 1}");
        assertEquals("no body named 'nobody'", Scenes.onlyProblem(l).message());
        assertEquals("$.run.expect[0].between[1]", Scenes.onlyProblem(l).path());
        l = Scenes.load("bad.yaml", SCENE.replace("landscape: {segments: [{from: [900, 0], to: [1100, 0]}]}", ""),
                "    - {metric: penetration.max, between: [sunk, landscape], of: max, atMost: 1}");
        assertEquals("the scene has no landscape", Scenes.onlyProblem(l).message());
        l = Scenes.load("bad.yaml", SCENE.replace("name: shelf", "name: landscape"),
                "    - {metric: penetration.max, between: [sunk, landscape], of: max, atMost: 1}");
        assertTrue(Scenes.onlyProblem(l).message().contains("names both a body and the scene's landscape"),
                Scenes.onlyProblem(l).message());
    }
}
