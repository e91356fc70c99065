package org.emini.harness.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.emini.harness.Scenes;
import org.junit.jupiter.api.Test;

/**
 * A scene that records every 0.45 s is still judged on every tick where an expectation reads an
 * extreme: a ball thrown up at 100 px/s under 100 px/s² peaks at y = -50 at t = 1 s (-49.92 in 60 ticks a
 * second), between the samples at 0.9 and 1.35 s (y = -49.5 and -43.9), which alone would pass every bound below.
 */
class EveryTickTest {
    private static final String THROW = String.join("\n",
            "world: {ticksPerSecond: 60}",
            "shapes: {ball: {type: circle, radius: 5}}",
            "bodies:",
            "  - {name: ball, shape: ball, position: [0, 0], velocity: [0, -100]}",
            "run:",
            "  duration: 1.8",
            "  record: {EVERY metrics: [energy], bodies: [ball]}",
            "  expect:",
            "    - {metric: body.ball.y, of: min, atLeast: -49.8}",
            "    - {body: ball, staysInside: {min: [-10, -49.8], max: [10, 500]}}",
            "    - {metric: energy.potential, of: max, atMost: 1e9}",
            "    - {metric: body.ball.y, of: final, atMost: 500}");

    private static SceneResult run(String every) {
        return ScenarioRunner.run(Scenes.valid("throw.yaml", THROW.replace("EVERY ", every)), n -> { });
    }

    @Test
    void anExtremeBetweenTwoSamplesFailsItsBound() {
        SceneResult r = run("every: 0.45, ");
        assertEquals(5, r.trace().size(), "the recorded trace keeps the scene's own samples");
        double sampledMin = Arrays.stream(r.trace().column("body.ball.y")).min().orElseThrow();
        assertTrue(sampledMin > -49.6, "the samples miss the peak: " + sampledMin);
        assertFalse(r.verdicts().get(0).passed(), r.verdicts().get(0).detail());
        assertEquals(-50, r.verdicts().get(0).measured(), 0.1);
        assertFalse(r.verdicts().get(1).passed(), r.verdicts().get(1).detail());
        assertEquals(0.2, r.verdicts().get(1).measured(), 0.1);
    }

    @Test
    void everyExtremeIsTheOneOfARunRecordedOnEveryTick() {
        SceneResult coarse = run("every: 0.45, ");
        SceneResult fine = run("");
        assertEquals(109, fine.trace().size());
        for (int i = 0; i < 3; i++) {
            assertEquals(fine.verdicts().get(i).measured(), coarse.verdicts().get(i).measured(), 0.0,
                    coarse.verdicts().get(i).expectation());
        }
        double sampledMax = Arrays.stream(coarse.trace().column("energy.potential")).max().orElseThrow();
        assertTrue(coarse.verdicts().get(2).measured() > sampledMax, "the metric's peak is between the samples too");
        assertEquals(coarse.trace().column("body.ball.y")[4], coarse.verdicts().get(3).measured(), 0.0,
                "a final value is read from the recorded trace");
    }

    /**
     * Two boxes created 4 px deep in each other without gravity are pushed apart, and a strong damping
     * (30% a tick) takes the kinetic energy away within a few ticks: the rise lies between the samples.
     */
    @Test
    void theEnergysRiseBetweenTwoSamplesCounts() {
        String scene = String.join("\n",
                "world: {ticksPerSecond: 60, gravity: [0, 0], damping: {lateral: 0.3}}",
                "shapes: {box: {type: rectangle, width: 20, height: 20}}",
                "bodies:",
                "  - {name: a, shape: box, position: [0, 0]}",
                "  - {name: b, shape: box, position: [16, 0]}",
                "run:",
                "  duration: 1",
                "  record: {EVERY metrics: [energy, stability], bodies: none}",
                "  expect:",
                "    - {stable: {maxEnergyRise: 0.001}}");
        SceneResult coarse = ScenarioRunner.run(Scenes.valid("push.yaml", scene.replace("EVERY ", "every: 0.5, ")), n -> { });
        SceneResult fine = ScenarioRunner.run(Scenes.valid("push.yaml", scene.replace("EVERY ", "")), n -> { });
        double[] sampled = coarse.trace().column("energy.total");
        double sampledRise = Arrays.stream(sampled).max().orElseThrow() - sampled[0];
        assertFalse(coarse.verdicts().get(0).passed(), coarse.verdicts().get(0).detail());
        assertEquals(fine.verdicts().get(0).measured(), coarse.verdicts().get(0).measured(), 0.0);
        assertTrue(coarse.verdicts().get(0).measured() > 10 * Math.max(sampledRise, 0.001),
                coarse.verdicts().get(0).measured() + " against the samples' " + sampledRise);
    }
}
