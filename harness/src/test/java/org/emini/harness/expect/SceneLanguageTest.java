package org.emini.harness.expect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.emini.harness.Scenes;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.SceneResult;
import org.junit.jupiter.api.Test;

/**
 * Issue 20's additions to the scene language: a group of bodies in one expectation (a generator's
 * {@code box[*]} or any {@code *} pattern), displacement and turn, the time of a first crossing, the order
 * of those times across a group, and a period from crossings; each against its closed form.
 */
class SceneLanguageTest {
    private static final String DROPS = String.join("\n",
            "world: {ticksPerSecond: 120, iterations: 10}",
            "shapes: {ball: {type: circle, radius: 5}}",
            "bodies:",
            "  - {name: drop1, shape: ball, position: [0, -100]}",
            "  - {name: drop2, shape: ball, position: [20, -200]}",
            "  - {name: drop3, shape: ball, position: [40, -300]}",
            "  - {name: other, shape: ball, position: [60, -50], gravity: false}",
            "run:",
            "  duration: 3",
            "  record: {bodies: [other]}",
            "  expect:");

    private static SceneResult run(String scene, String... expect) {
        return ScenarioRunner.run(Scenes.valid("language.yaml", scene + "\n" + String.join("\n", expect)), n -> { });
    }

    @Test
    void aGroupsFirstCrossingsComeInOrderAtTheFreeFallTimes() {
        SceneResult r = run(DROPS,
                "    - {metric: 'body.drop*.y', of: firstCrossing, crossing: 0, inOrder: true}",
                "    - {metric: body.drop3.y, of: firstCrossing, crossing: 0, near: 2.449, tolerance: 0.01}");
        // Every drop is recorded though record names only `other`: t = sqrt(2 h / g) = 1.414, 2, 2.449 s.
        assertTrue(r.trace().bodies().containsAll(List.of("drop1", "drop2", "drop3")), r.trace().bodies().toString());
        assertTrue(r.verdicts().get(0).passed(), r.verdicts().get(0).detail());
        assertTrue(r.verdicts().get(0).detail().contains("3 bodies cross in order"), r.verdicts().get(0).detail());
        assertTrue(r.verdicts().get(1).passed(), r.verdicts().get(1).detail());
        assertEquals(Math.sqrt(6), r.verdicts().get(1).measured(), 0.01);
        // Reversed (highest first) the order fails, naming the pair.
        SceneResult up = run(DROPS.replace("[0, -100]", "[0, -400]"),
                "    - {metric: 'body.drop*.y', of: firstCrossing, crossing: 0, inOrder: true}");
        assertFalse(up.verdicts().get(0).passed());
        assertTrue(up.verdicts().get(0).detail().startsWith("drop2 crosses at"), up.verdicts().get(0).detail());
    }

    @Test
    void aGroupBoundHoldsForEveryMemberAndNamesTheOneThatFails() {
        // After 1 s of free fall each drop has moved g t^2 / 2 = 50 px: displacement from its start.
        SceneResult r = run(DROPS,
                "    - {metric: 'body.drop*.displacement', at: 1, near: 50, tolerance: 0.5}",
                "    - {metric: 'body.drop*.displacement', of: final, atMost: 400}");
        assertTrue(r.verdicts().get(0).passed(), r.verdicts().get(0).detail());
        // drop1 lands (on nothing: it falls on) ... at 3 s all have moved 450 px: all three fail.
        assertFalse(r.verdicts().get(1).passed());
        assertTrue(r.verdicts().get(1).detail().contains("3 of 3 bodies fail"), r.verdicts().get(1).detail());
    }

    @Test
    void aGeneratorsBodiesAreAGroupAndTurnCountsFromTheStart() {
        SceneResult r = ScenarioRunner.run(Scenes.valid("tower.yaml",
                "world: {ticksPerSecond: 20}",
                "shapes: {ground: {type: rectangle, width: 800, height: 40}, box: {type: rectangle, width: 20, height: 20}}",
                "bodies:",
                "  - {name: ground, shape: ground, position: [0, 20], static: true}",
                "  - {name: spinner, shape: box, position: [300, -300], angle: 1, angularVelocity: 3, gravity: false}",
                "generators: [{type: tower, name: box, shape: box, base: [0, -10], count: 5}]",
                "run:",
                "  duration: 2",
                "  record: {bodies: none}",
                "  expect:",
                "    - {metric: 'body.box[*].displacement', of: max, atMost: 1}",
                "    - {metric: body.spinner.turn, of: final, near: 6, tolerance: 0.001}"), n -> { });
        assertTrue(r.verdicts().get(0).passed(), r.verdicts().get(0).detail());
        assertEquals(5, r.trace().bodies().stream().filter(b -> b.startsWith("box[")).count());
        assertTrue(r.verdicts().get(1).passed(), r.verdicts().get(1).detail());
    }

    @Test
    void aPendulumsPeriodComesFromItsCrossings() {
        // L = 100 px, g = 100 px/s^2, 0.1 rad: T = 2 pi sqrt(L / g) (1 + theta^2 / 16) = 6.2871 s.
        SceneResult r = ScenarioRunner.run(Scenes.valid("pendulum.yaml",
                "world: {ticksPerSecond: 240}",
                "bodies:",
                "  - {name: pivot, shape: {type: rectangle, width: 4, height: 4}, position: [0, 0], static: true}",
                "  - {name: bob, shape: {type: circle, radius: 2}, position: [9.9833, 99.5004]}",
                "joints: [{bodyA: pivot, bodyB: bob, at: [0, 0]}]",
                "run:",
                "  duration: 20",
                "  expect:",
                "    - {metric: body.bob.x, of: period, near: 6.2871, tolerance: 0.02}"), n -> { });
        assertTrue(r.verdicts().get(0).passed(), r.verdicts().get(0).detail());
    }

    @Test
    void oneChannelAgainstAnotherAndBoundsRelativeToAMeasuredFigure() {
        // drop1 and drop2 fall side by side 100 px apart: y2 - y1 stays -100 exactly while both fall freely.
        SceneResult r = run(DROPS,
                "    - {metric: body.drop2.y, minus: body.drop1.y, of: maxAbs, near: 100, tolerance: 0.01}",
                // At 2 s drop3 moves at g t = 200 px/s: at least 95% of that is 190 px/s, measured 200.
                "    - {metric: body.drop3.speed, at: 2, atLeast: 0.95, relativeTo: {metric: body.drop3.speed, at: 2}}",
                // Its speed at 1 s is half of that at 2 s: not at least 95% of it.
                "    - {metric: body.drop3.speed, at: 1, atLeast: 0.95, relativeTo: {metric: body.drop3.speed, at: 2}}");
        assertTrue(r.verdicts().get(0).passed(), r.verdicts().get(0).detail());
        assertTrue(r.verdicts().get(1).passed(), r.verdicts().get(1).detail());
        assertFalse(r.verdicts().get(2).passed());
        assertTrue(r.verdicts().get(2).detail().contains("≥ 190") && r.verdicts().get(2).detail().contains("= 200"),
                r.verdicts().get(2).detail());
        ScenarioLoader.Loaded l = Scenes.load("bad.yaml", DROPS,
                "    - {metric: body.drop1.y, minus: body.nobody.y, of: max, atMost: 1}");
        assertEquals("no body named 'nobody' (minus takes one channel, not a group)", Scenes.onlyProblem(l).message());
    }

    @Test
    void aGroupThatMatchesNothingAndTimingWithoutItsValueAreLocatedProblems() {
        ScenarioLoader.Loaded l = Scenes.load("bad.yaml", DROPS, "    - {metric: 'body.nothing*.y', of: max, atMost: 1}");
        assertEquals("'nothing*' matches no body", Scenes.onlyProblem(l).message());
        l = Scenes.load("bad.yaml", DROPS, "    - {metric: body.drop1.y, of: firstCrossing, atMost: 1}");
        assertTrue(Scenes.onlyProblem(l).message().contains("needs `crossing`"), Scenes.onlyProblem(l).message());
        l = Scenes.load("bad.yaml", DROPS, "    - {metric: body.drop1.y, of: max, inOrder: true}");
        assertTrue(Scenes.onlyProblem(l).message().contains("inOrder belongs"), Scenes.onlyProblem(l).message());
    }
}
