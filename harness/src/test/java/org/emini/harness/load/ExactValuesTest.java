package org.emini.harness.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import org.emini.harness.Repo;
import org.emini.harness.Scenes;
import org.emini.harness.scenario.Scenario;
import org.junit.jupiter.api.Test;

/**
 * A value the harness cannot keep as written is refused where it is written, never changed in silence:
 * integers that would wrap, numbers that float (the engine's precision) makes infinite or zero, octal
 * look-alikes.
 */
class ExactValuesTest {

    private static Problem only(ScenarioLoader.Loaded loaded) {
        return Scenes.onlyProblem(loaded);
    }

    /** Issue 14: 4294967297 read as an int is 1; the scene built one body and passed. */
    @Test
    void aCountAbove2To31IsRefusedNotWrapped() {
        Problem p = only(Scenes.load("wrap.yaml",
                "shapes: {b: {type: circle, radius: 1}}",
                "generators:",
                "  - {type: tower, name: t, shape: b, base: [0, 0], count: 4294967297}",
                "run: {duration: 1}"));
        assertEquals("$.generators[0].count", p.path());
        assertEquals(3, p.line());
    }

    /** Issue 14: 1e-400 read as a double is 0: the run had 0 ticks. */
    @Test
    void aDurationThatUnderflowsIsRefused() {
        Problem p = only(Scenes.load("tiny.yaml", "run: {duration: 1e-400}"));
        assertEquals("$.run.duration", p.path());
        assertEquals(1, p.line());
        assertEquals(17, p.column());
        assertTrue(p.message().contains("too small"), p.message());
    }

    @Test
    void numbersBeyondFloatAreRefusedWhereverTheyAre() {
        for (String v : List.of("1e400", "-1e400", "1e39", "340282356779733661637539395458142568448")) {
            Problem p = only(Scenes.load("big.yaml",
                    "bodies: [{name: a, shape: {type: circle, radius: 1}, position: [" + v + ", 0]}]",
                    "run: {duration: 1}"));
            assertEquals("$.bodies[0].position[0]", p.path(), v);
            assertTrue(p.message().contains("out of range"), p.message());
        }
        for (String v : List.of("1e-46", "-1e-400")) {
            Problem p = only(Scenes.load("small.yaml",
                    "bodies: [{name: a, shape: {type: circle, radius: 1}, velocity: [0, " + v + "]}]",
                    "run: {duration: 1}"));
            assertEquals("$.bodies[0].velocity[1]", p.path(), v);
        }
    }

    @Test
    void floatLimitsThemselvesAreKept() {
        Scenario s = Scenes.valid("edge.yaml",
                "bodies: [{name: a, shape: {type: circle, radius: 1}, position: [3.4e38, 1.5e-45], static: true}]",
                "run: {duration: 1}");
        assertEquals(3.4e38, s.bodies().get(0).x());
    }

    @Test
    void aLeadingZeroIsRefusedRatherThanReadAsOctal() {
        Problem p = only(Scenes.load("octal.yaml",
                "particles: [{from: [0, 0], maxCount: 017}]",
                "run: {duration: 1}"));
        assertEquals("$.particles[0].maxCount", p.path());
        assertTrue(p.message().contains("octal"), p.message());
    }

    @Test
    void seedsAre64BitIntegers() {
        String ok = "particles: [{from: [0, 0], seed: 9223372036854775807}]";
        assertTrue(Scenes.load("seed.yaml", ok, "run: {duration: 1}").ok());
        Problem p = only(Scenes.load("seed.yaml", ok.replace("807", "808"), "run: {duration: 1}"));
        assertEquals("$.particles[0].seed", p.path());
    }

    /**
     * Every integer of the schema is bounded within what the reader narrows it to (int; long for seeds),
     * so no integer can wrap: a new integer field without bounds fails here.
     */
    @Test
    void everyIntegerInTheSchemaHasBoundsThatFitItsJavaType() throws Exception {
        JsonNode schema = new ObjectMapper().readTree(Repo.schema().toFile());
        List<String> unbounded = new ArrayList<>();
        walk(schema, "$", unbounded);
        assertEquals(List.of(), unbounded);
    }

    private static void walk(JsonNode node, String at, List<String> unbounded) {
        if (node.isObject()) {
            if ("integer".equals(node.path("type").asText()) && !at.endsWith("issue")) {
                BigInteger lo = BigInteger.valueOf(at.endsWith("seed") ? Long.MIN_VALUE : Integer.MIN_VALUE);
                BigInteger hi = BigInteger.valueOf(at.endsWith("seed") ? Long.MAX_VALUE : Integer.MAX_VALUE);
                boolean bounded = node.has("minimum") && node.has("maximum")
                        && node.get("minimum").bigIntegerValue().compareTo(lo) >= 0
                        && node.get("maximum").bigIntegerValue().compareTo(hi) <= 0;
                if (!bounded) {
                    unbounded.add(at);
                }
            }
            for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext();) {
                Map.Entry<String, JsonNode> e = it.next();
                walk(e.getValue(), at + "." + e.getKey(), unbounded);
            }
        } else if (node.isArray()) {
            for (int i = 0; i < node.size(); i++) {
                walk(node.get(i), at + "[" + i + "]", unbounded);
            }
        }
    }
}
