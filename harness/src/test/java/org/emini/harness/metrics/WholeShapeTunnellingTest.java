package org.emini.harness.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.harness.Scenes;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.Trace;
import org.junit.jupiter.api.Test;

/** tunnelling with points: shape: a rod's tip passing a wall line counts, though its centre stays short of it. */
class WholeShapeTunnellingTest {
    private static double crossings(String points) {
        Trace t = ScenarioRunner.run(Scenes.valid("rod.yaml",
                "world: {gravity: [0, 0], ticksPerSecond: 60}",
                "bodies: [{name: rod, shape: {type: rectangle, width: 40, height: 4}, position: [-30, 0], velocity: [250, 0]}]",
                "run: {duration: 0.1, record: {metrics: [{tunnelling: {walls: [{from: [0, -100], to: [0, 100]}]" + points + "}}]}}"),
                n -> { }).trace();
        double[] c = t.column("tunnelling.count");
        return c[c.length - 1];
    }

    @Test
    void theTipCountsOnceWhenTheShapeIsWatchedAndNotWhenOnlyTheCentreIs() {
        // The centre moves from -30 to -5 px: short of the line at x = 0. The right end, 20 px ahead, passes it.
        assertEquals(0, crossings(""));
        assertEquals(0, crossings(", points: centre"));
        // Both right corners cross in the same tick: one count for the body.
        assertEquals(1, crossings(", points: shape"));
    }
}
