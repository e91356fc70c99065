package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.emini.dynamics.SolverSettings;
import org.emini.harness.Scenes;
import org.emini.harness.scenario.Scenario;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/** {@code run --nudge}: the engine's speculative distance scaled in the world a scene builds, nothing else. */
class NudgedSceneTest {
    private static final String BALL = "bodies: [{name: ball, shape: {type: circle, radius: 5}}]";

    private static SolverSettings built(Scenario s) throws Exception {
        return WorldBuilder.build(s).world().getSolverSettings();
    }

    @Test
    void aSceneWithoutItsOwnDistanceGetsTheDefaultTimesTheFactor() throws Exception {
        Scenario plain = Scenes.valid("plain.yaml", BALL, "run: {duration: 1}");
        SolverSettings defaults = new SolverSettings();
        SolverSettings nudged = built(plain.withNudge(1.02, WorldBuilder.defaultSpeculativeDistance()));
        assertEquals((float) (defaults.getSpeculativeDistance() * 1.02), nudged.getSpeculativeDistance());
        assertEquals(defaults.getLinearSlop(), nudged.getLinearSlop());
        assertEquals(defaults.getSpeculativeDistance(), built(plain).getSpeculativeDistance(), "the scene itself is kept");
    }

    @Test
    void aSceneWithItsOwnDistanceHasItScaledAndKeepsItsOtherTunables() throws Exception {
        Scenario own = Scenes.valid("own.yaml", "world: {solver: {speculativeDistance: 2, linearSlop: 0.1}}", BALL,
                "run: {duration: 1}");
        SolverSettings nudged = built(own.withNudge(0.98, WorldBuilder.defaultSpeculativeDistance()));
        assertEquals((float) (2 * 0.98), nudged.getSpeculativeDistance());
        assertEquals(0.1f, nudged.getLinearSlop());
    }

    @Test
    void aFactorThatIsNotFiniteAndPositiveIsRefused() {
        Scenario plain = Scenes.valid("plain.yaml", BALL, "run: {duration: 1}");
        for (double f : new double[] {0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> plain.withNudge(f, 0.5));
            assertEquals("nudge factor must be finite and > 0, was " + f, e.getMessage());
        }
    }

    @Test
    void aWorldWithoutContactsTicksBitForBitAlikeNudged() throws Exception {
        // Only contacts read the speculative distance: a falling ball must not notice it.
        Scenario plain = Scenes.valid("plain.yaml", BALL, "run: {duration: 1}");
        World a = WorldBuilder.build(plain).world();
        World b = WorldBuilder.build(plain.withNudge(1.5, WorldBuilder.defaultSpeculativeDistance())).world();
        for (int t = 0; t < 20; t++) {
            a.tick();
            b.tick();
        }
        assertEquals(1, b.getBodies().length);
        // JUnit compares floats bit for bit.
        assertEquals(a.getBodies()[0].getY(), b.getBodies()[0].getY());
        assertEquals(a.getBodies()[0].getVelocityY(), b.getBodies()[0].getVelocityY());
    }
}
