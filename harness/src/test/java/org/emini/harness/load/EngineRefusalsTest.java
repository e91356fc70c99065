package org.emini.harness.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.harness.Scenes;
import org.junit.jupiter.api.Test;

/**
 * {@code validate} refuses what the builder would (issue 14: 1,757 files passed validate and were refused
 * at build, with no line): it builds the world through the same builder, and the engine's refusal is
 * reported where the scene writes the value.
 */
class EngineRefusalsTest {

    private static Problem only(ScenarioLoader.Loaded loaded) {
        return Scenes.onlyProblem(loaded);
    }

    @Test
    void aNonConvexPolygonIsRefusedAtItsShape() {
        Problem p = only(Scenes.load("dart.yaml",
                "shapes:",
                "  dart: {type: polygon, vertices: [[0, 0], [10, -10], [2, 0], [10, 10]]}",
                "bodies: [{name: a, shape: dart}]",
                "run: {duration: 1}"));
        assertEquals("$.shapes.dart", p.path());
        assertEquals(2, p.line());
        assertTrue(p.message().startsWith("the engine refuses it: "), p.message());
    }

    @Test
    void aJointOfABodyWithItselfIsRefusedAtTheJoint() {
        Problem p = only(Scenes.load("self.yaml",
                "bodies: [{name: a, shape: {type: circle, radius: 5}}]",
                "joints:",
                "  - {bodyA: a, bodyB: a, at: [0, 0]}",
                "run: {duration: 1}"));
        assertEquals("$.joints[0]", p.path());
        assertEquals(3, p.line());
        assertTrue(p.message().contains("must differ"), p.message());
    }

    @Test
    void aSolverSettingTheSchemaAllowsButTheEngineRefusesIsLocated() {
        Problem p = only(Scenes.load("push.yaml", "world: {solver: {contactPushMaxVelocity: 0}}", "run: {duration: 1}"));
        assertEquals("$.world.solver.contactPushMaxVelocity", p.path());
        assertEquals(1, p.line());
        assertTrue(p.message().contains("SolverSettings.setContactPushMaxVelocity"), p.message());
    }

    @Test
    void iterationsAboveTheEnginesRangeAreRefused() {
        Problem p = only(Scenes.load("it.yaml", "world: {iterations: 1001}", "run: {duration: 1}"));
        assertEquals("$.world.iterations", p.path());
        assertEquals(1, p.line());
    }

    @Test
    void aGeneratedBodyTheEngineRefusesNamesItsGenerator() {
        Problem p = only(Scenes.load("gen.yaml",
                "shapes: {b: {type: circle, radius: 1}}",
                "generators:",
                "  - {type: row, name: r, shape: b, start: [3.0e38, 0], count: 3, spacing: [2.0e38, 0]}",
                "run: {duration: 1}"));
        assertEquals("$.generators[0]", p.path());
        assertEquals(3, p.line());
    }

    @Test
    void aSpringOfABodyWithItselfIsRefusedAtTheSpring() {
        Problem p = only(Scenes.load("spring.yaml",
                "bodies: [{name: a, shape: {type: circle, radius: 5}}]",
                "springs: [{bodyA: a, bodyB: a, stiffness: 10}]",
                "run: {duration: 1}"));
        assertEquals("$.springs[0]", p.path());
        assertEquals(2, p.line());
    }
}
