package org.emini.harness.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.emini.harness.Scenes;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.Status;
import org.junit.jupiter.api.Test;

/**
 * No scene can exhaust the harness: documents, generators, runs and pools have limits (Limits), each
 * refused as a located problem. Before them, each of these inputs ran into an OutOfMemoryError.
 */
class SizeLimitsTest {

    private static Problem only(ScenarioLoader.Loaded loaded) {
        return Scenes.onlyProblem(loaded);
    }

    /** Issue 14's bomb: 100 items, then 16 levels of three aliases of the level below (4.3e9 values). */
    @Test
    void anAliasBombWithinSnakeYamlsAliasLimitIsRefusedAtItsPlace() {
        List<String> lines = new ArrayList<>();
        lines.add("a0: &a0 [" + String.join(", ", java.util.Collections.nCopies(100, "1")) + "]");
        for (int i = 1; i <= 16; i++) {
            lines.add("a" + i + ": &a" + i + " [*a" + (i - 1) + ", *a" + (i - 1) + ", *a" + (i - 1) + "]");
        }
        lines.add("run: {duration: 1}");
        Problem p = only(Scenes.load("bomb.yaml", lines.toArray(new String[0])));
        assertTrue(p.message().contains("once aliases are expanded"), p.toString());
        assertTrue(p.line() >= 1 && p.column() >= 1, p.toString());
        assertTrue(p.path().startsWith("$.a"), p.toString());
    }

    @Test
    void anAliasInsideItsOwnAnchorIsRefused() {
        Problem p = only(Scenes.load("loop.yaml", "loop: &x [1, *x]", "run: {duration: 1}"));
        assertEquals(1, p.line(), p.toString());
        assertTrue(p.message().contains("nested more than"), p.toString());
    }

    @Test
    void deepNestingIsRefusedWithItsLine() {
        String deep = "[".repeat(60) + "]".repeat(60);
        Problem p = only(Scenes.load("deep.yaml", "run: {duration: 1}", "tags: " + deep));
        assertEquals(2, p.line(), p.toString());
        assertTrue(p.message().contains("nested more than " + Limits.DEPTH), p.toString());
    }

    @Test
    void moreAliasesThanSnakeYamlAllowsAreRefusedWithALine() {
        List<String> lines = new ArrayList<>(List.of("a: &a [1]", "b:"));
        for (int i = 0; i < Limits.COLLECTION_ALIASES + 1; i++) {
            lines.add("  - *a");
        }
        lines.add("run: {duration: 1}");
        Problem p = only(Scenes.load("aliases.yaml", lines.toArray(new String[0])));
        assertTrue(p.line() > 2, p.toString());
        assertTrue(p.message().contains("aliases"), p.toString());
    }

    @Test
    void aDocumentOfTooManyValuesIsRefusedWhileItIsRead() {
        String many = "[" + "0,".repeat(Limits.EVENTS) + "0]";
        Problem p = only(Scenes.load("many.yaml", "run: {duration: 1}", "tags: " + many));
        assertEquals(2, p.line(), p.toString());
        assertTrue(p.message().contains("too large"), p.toString());
    }

    /** Issue 14: count: 100000000 ended in an OutOfMemoryError after 38 s. */
    @Test
    void aGeneratorOfAHundredMillionBodiesIsRefusedBeforeExpanding() {
        Problem p = only(Scenes.load("many.yaml",
                "shapes: {b: {type: circle, radius: 1}}",
                "generators:",
                "  - {type: row, name: r, shape: b, start: [0, 0], count: 100000000}",
                "run: {duration: 1}"));
        assertEquals("$.generators[0].count", p.path());
        assertEquals(3, p.line());
    }

    @Test
    void generatorsTogetherMayNotPassTheBodyLimit() {
        Problem p = only(Scenes.load("grid.yaml",
                "shapes: {b: {type: circle, radius: 1}}",
                "generators:",
                "  - {type: grid, name: g, shape: b, origin: [0, 0], columns: 1000, rows: 1000, spacing: [3, 3]}",
                "run: {duration: 1}"));
        assertEquals("$.generators[0]", p.path());
        assertEquals(3, p.line());
        assertTrue(p.message().contains("1000000 bodies"), p.message());
    }

    /** Issue 14: duration: 1e300 passed validate and ran out of memory in run. */
    @Test
    void aHugeDurationIsRefused() {
        Problem p = only(Scenes.load("long.yaml", "run: {duration: 1e300}"));
        assertEquals("$.run.duration", p.path());
        assertEquals(1, p.line());
    }

    @Test
    void tooManyTicksAreRefusedAtTheDuration() {
        Problem p = only(Scenes.load("ticks.yaml", "world: {timestep: 0.0001}", "run: {duration: 3600}"));
        assertEquals("$.run.duration", p.path());
        assertTrue(p.message().contains("ticks"), p.message());
    }

    @Test
    void bodiesTimesTicksHaveALimit() {
        Problem p = only(Scenes.load("work.yaml",
                "shapes: {b: {type: circle, radius: 1}}",
                "generators:",
                "  - {type: row, name: r, shape: b, start: [0, 0], count: 100000, spacing: [3, 0]}",
                "run: {duration: 3600, record: {bodies: none}}"));
        assertEquals("$.run.duration", p.path());
        assertTrue(p.message().contains("body-ticks"), p.message());
    }

    @Test
    void aTraceTooLargeToKeepIsRefusedAtTheRecord() {
        Problem p = only(Scenes.load("trace.yaml",
                "shapes: {b: {type: circle, radius: 1}}",
                "generators:",
                "  - {type: row, name: r, shape: b, start: [0, 0], count: 1000, spacing: [3, 0]}",
                "run: {duration: 3600}"));
        assertEquals("$.run.record", p.path());
    }

    /** Sampled once a minute the trace is small, but the bound on every member's lowest point is judged every tick. */
    @Test
    void extremesJudgedEveryTickCountInTheTracesLimit() {
        String[] scene = {
            "shapes: {b: {type: circle, radius: 1}}",
            "generators:",
            "  - {type: row, name: r, shape: b, start: [0, 0], count: 1000, spacing: [3, 0]}",
            "run:",
            "  duration: 600",
            "  record: {every: 60, bodies: none}",
            "  expect: [{metric: 'body.r[*].y', of: OF, atMost: 1000}]"};
        Problem p = only(Scenes.load("extremes.yaml", String.join("\n", scene).replace("OF", "max")));
        assertEquals("$.run.expect", p.path());
        assertTrue(p.message().contains("judged on every tick"), p.message());
        // Read at the samples alone (the final value) the same scene is within the limits.
        assertTrue(Scenes.load("extremes.yaml", String.join("\n", scene).replace("OF", "final")).problems().isEmpty());
    }

    @Test
    void particlePoolsHaveALimit() {
        List<String> lines = new ArrayList<>(List.of("particles:"));
        for (int i = 0; i < 11; i++) {
            lines.add("  - {from: [0, 0], maxCount: 100000}");
        }
        lines.add("run: {duration: 1}");
        Problem p = only(Scenes.load("pools.yaml", lines.toArray(new String[0])));
        assertEquals("$.particles", p.path());
        assertEquals(1, p.line());
    }

    /** Named multi-shapes nest by reference: ten levels of three parts would be 59,049 polygons. */
    @Test
    void nestedNamedMultiShapesHaveAPartLimit() {
        List<String> lines = new ArrayList<>(List.of("shapes:", "  s0: {type: circle, radius: 1}"));
        for (int i = 1; i <= 10; i++) {
            String part = "{shape: s" + (i - 1) + "}";
            lines.add("  s" + i + ": {type: multiShape, parts: [" + part + ", " + part + ", " + part + "]}");
        }
        lines.add("run: {duration: 1}");
        ScenarioLoader.Loaded loaded = Scenes.load("nest.yaml", lines.toArray(new String[0]));
        assertFalse(loaded.ok());
        Problem p = loaded.problems().get(0);
        assertEquals("$.shapes.s7.parts", p.path(), loaded.problems().toString());
        assertEquals(9, p.line());
    }

    @Test
    void anActionAfterTheRunWouldNeverHappen() {
        Problem p = only(Scenes.load("late.yaml",
                "bodies: [{name: a, shape: {type: circle, radius: 1}}]",
                "actions: [{at: 5, type: impulse, body: a, impulse: [1, 0]}]",
                "run: {duration: 1}"));
        assertEquals("$.actions[0].at", p.path());
        assertEquals(2, p.line());
    }

    /** A fuzz finding: boxes 99999 px tall in a pyramid all overlap; the first tick paired 12.7 million of them. */
    @Test
    void thousandsOfBodiesOverlappingAtTheStartAreRefused() {
        Problem p = only(Scenes.load("tall.yaml",
                "shapes: {box: {type: rectangle, width: 20, height: 99999}}",
                "generators:",
                "  - {type: pyramid, name: box, shape: box, base: [0, -10], rows: 100, spacing: [21, 20]}",
                "run: {duration: 1, record: {bodies: none}}"));
        assertEquals("$.generators[0]", p.path());
        assertEquals(3, p.line());
        assertTrue(p.message().contains("overlap at the start"), p.message());
    }

    @Test
    void aBodyBeyondTheCoordinatesAFloatResolvesIsRefused() {
        Problem p = only(Scenes.load("far.yaml",
                "bodies: [{name: a, shape: {type: circle, radius: 1}, position: [2.0e7, 0]}]",
                "run: {duration: 1}"));
        assertEquals("$.bodies[0]", p.path());
        assertTrue(p.message().contains("beyond"), p.message());
    }

    /**
     * A fuzz finding: gravity -1e30 (now out of the schema's bounds; a velocity of 1e30 still does it)
     * sent 20,000 bodies to 1e26 px in one tick, where they share float coordinates and the broadphase
     * pairs them all. The run now stops at the first tick a body leaves ±1e7 px, with an error naming it.
     */
    @Test
    void theRunStopsWhenABodyLeavesTheCoordinatesAFloatResolves() {
        SceneResult r = ScenarioRunner.run(Scenes.valid("v.yaml",
                "bodies: [{name: ball, shape: {type: circle, radius: 1}, velocity: [0, 1.0e30]}]",
                "run: {duration: 1}"), n -> { });
        assertEquals(Status.ERROR, r.status());
        assertTrue(r.message().startsWith("at tick 1: body 'ball' is at (0.0, "), r.message());
        assertTrue(r.message().contains("beyond ±1.0E7 px"), r.message());
    }

    /** A run still ticking after its time limit stops with an error (a limit of a nanosecond: the first tick). */
    @Test
    void aRunOverItsTimeLimitStopsWithAnError() {
        SceneResult r = ScenarioRunner.run(Scenes.valid("t.yaml",
                "bodies: [{name: ball, shape: {type: circle, radius: 1}}]",
                "run: {duration: 1}"), n -> { }, 1e-9);
        assertEquals(Status.ERROR, r.status());
        assertTrue(r.message().startsWith("over the time limit of 0 s at tick 1 of 20"), r.message());
    }

    /**
     * A fuzz finding: gravity [2147483648, 200] on 5,000 rain bodies stretched every broadphase box over
     * the whole container in the first tick, and pairing them never ended. Gravity and the tick have bounds.
     */
    @Test
    void gravityAndTheTickHaveBounds() {
        Problem g = only(Scenes.load("g.yaml", "world: {gravity: [2147483648, 200]}", "run: {duration: 1}"));
        assertEquals("$.world.gravity[0]", g.path());
        assertEquals(1, g.line());
        Problem a = only(Scenes.load("a.yaml", "actions: [{at: 0, type: gravity, gravity: [0, -1.0e6]}]",
                "run: {duration: 1}"));
        assertEquals("$.actions[0].gravity[1]", a.path());
        assertEquals("$.world.timestep", only(Scenes.load("h.yaml", "world: {timestep: 2}", "run: {duration: 10}")).path());
        assertEquals("$.world.ticksPerSecond",
                only(Scenes.load("t.yaml", "world: {ticksPerSecond: 0.5}", "run: {duration: 10}")).path());
    }
}
