package org.emini.harness.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.emini.harness.Scenes;
import org.junit.jupiter.api.Test;

/** Invalid scenes are rejected with the file, line, path and problem named. */
class SchemaErrorsTest {

    private static Problem only(ScenarioLoader.Loaded loaded) {
        return Scenes.onlyProblem(loaded);
    }

    @Test
    void unknownKeyIsAnErrorAtItsLine() {
        Problem p = only(Scenes.load("scene.yaml",
                "world:",
                "  gravity: [0, 100]",
                "  gravty: [0, 10]",
                "run: {duration: 1}"));
        assertEquals("scene.yaml", p.file());
        assertEquals(3, p.line());
        assertEquals("$.world.gravty", p.path());
        assertTrue(p.message().contains("unknown key 'gravty'"), p.message());
        assertTrue(p.toString().startsWith("scene.yaml:3:3: $.world.gravty: "), p.toString());
    }

    @Test
    void unknownKeyInsideATypedShapeIsAnError() {
        Problem p = only(Scenes.load("s.yaml",
                "shapes:",
                "  ball: {type: circle, radius: 5, width: 3}",
                "run: {duration: 1}"));
        assertEquals(2, p.line());
        assertEquals("$.shapes.ball.width", p.path());
    }

    @Test
    void wrongValueNamesItsPathAndLine() {
        Problem p = only(Scenes.load("s.yaml",
                "bodies:",
                "  - shape: {type: circle, radius: 5}",
                "  - shape: {type: circle, radius: -5}",
                "run: {duration: 1}"));
        assertEquals(3, p.line());
        assertEquals("$.bodies[1].shape.radius", p.path());
        assertTrue(p.message().contains("minimum"), p.message());
    }

    @Test
    void missingRequiredKeyPointsAtTheObject() {
        Problem p = only(Scenes.load("s.yaml",
                "shapes:",
                "  box: {type: rectangle, width: 5}",
                "run: {duration: 1}"));
        assertEquals(2, p.line());
        assertEquals("$.shapes.box", p.path());
        assertTrue(p.message().contains("height"), p.message());
    }

    @Test
    void jsonFilesGetLinesToo() {
        Problem p = only(Scenes.load("s.json",
                "{",
                "  \"run\": {",
                "    \"duration\": 1,",
                "    \"expect\": [ {\"stable\": {}, \"colour\": \"red\"} ]",
                "  }",
                "}"));
        assertEquals(4, p.line());
        assertEquals("$.run.expect[0].colour", p.path());
    }

    @Test
    void syntaxErrorsAreLocated() {
        ScenarioLoader.Loaded loaded = Scenes.load("s.yaml", "run:", "  duration: [1", "world: {}");
        assertFalse(loaded.ok());
        assertTrue(loaded.problems().get(0).line() >= 2, loaded.problems().toString());
        assertTrue(loaded.problems().get(0).message().startsWith("cannot parse"));
    }

    @Test
    void duplicateKeysAreErrors() {
        Problem p = only(Scenes.load("s.yaml", "run: {duration: 1}", "run: {duration: 2}"));
        assertEquals(2, p.line());
        assertTrue(p.message().contains("duplicate key"), p.message());
    }

    @Test
    void unknownNamesAreCaughtAfterTheSchema() {
        ScenarioLoader.Loaded loaded = Scenes.load("s.yaml",
                "bodies:",
                "  - {name: a, shape: boxx}",
                "actions:",
                "  - {at: 1, type: impulse, body: b, impulse: [1, 0]}",
                "run: {duration: 1}");
        List<Problem> problems = loaded.problems();
        assertEquals(2, problems.size(), problems.toString());
        assertEquals("$.bodies[0].shape", problems.get(0).path());
        assertEquals(2, problems.get(0).line());
        assertEquals("$.actions[0].body", problems.get(1).path());
        assertEquals(4, problems.get(1).line());
    }

    @Test
    void exclusiveKeysAreRejected() {
        Problem p = only(Scenes.load("s.yaml", "world: {ticksPerSecond: 60, timestep: 0.01}", "run: {duration: 1}"));
        assertEquals("$.world.timestep", p.path());
        assertEquals(1, p.line());
    }

    @Test
    void expectationsMustBeBoundedAndKnown() {
        ScenarioLoader.Loaded loaded = Scenes.load("s.yaml",
                "run:",
                "  duration: 1",
                "  expect:",
                "    - {metric: energy.totl, of: final, atMost: 1}",
                "    - {metric: energy.total, of: final}",
                "    - {closedForm: body.x.y, of: maxError, atMost: 1}");
        // The third has two problems: an unknown body and no closed form to compare with.
        assertEquals(4, loaded.problems().size(), loaded.problems().toString());
        assertEquals(4, loaded.problems().get(0).line());
    }
}
