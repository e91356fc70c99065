package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.emini.dynamics.SolverSettings;
import org.emini.harness.Scenes;
import org.emini.harness.scenario.Scenario;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * {@code run --nudge}: the engine's speculative distance scaled in the world a scene builds, and gravity
 * by a few parts per million, nothing else.
 */
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
    void gravityIsScaledByATenThousandthOfTheNudgeWhereverTheSceneSetsIt() throws Exception {
        Scenario s = Scenes.valid("g.yaml", "world: {gravity: [30, 200]}", BALL,
                "actions: [{at: 0.5, type: gravity, gravity: [0, -50]}]", "run: {duration: 1}");
        double g = Scenario.gravityNudge(1.02);
        assertEquals(1.000002, g, 1e-15);
        Scenario nudged = s.withNudge(1.02, WorldBuilder.defaultSpeculativeDistance());
        assertEquals(30 * g, nudged.world().gravityX());
        assertEquals(200 * g, nudged.world().gravityY());
        assertEquals(-50 * g, nudged.actions().get(0).vector()[1]);
        assertEquals(0.0, nudged.actions().get(0).vector()[0]);
        World w = WorldBuilder.build(nudged).world();
        assertEquals((float) (200 * g), w.getGravityY());
        assertNotEquals(200f, w.getGravityY(), "two parts per million must change the float");
        assertEquals(-50.0, s.actions().get(0).vector()[1], "the scene itself is kept");
    }

    @Test
    void aWorldWithoutGravityOrContactsTicksBitForBitAlikeNudged() throws Exception {
        // Only contacts read the speculative distance and only gravity is scaled: a ball flying
        // without gravity must not notice the nudge.
        Scenario plain = Scenes.valid("plain.yaml", "world: {gravity: [0, 0]}",
                "bodies: [{name: ball, shape: {type: circle, radius: 5}, velocity: [3, 7], angularVelocity: 1}]",
                "run: {duration: 1}");
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
        assertEquals(a.getBodies()[0].getAngle(), b.getBodies()[0].getAngle());
    }

    @Test
    void aFallingBallNoticesTheNudgeOnlyInItsRoundOff() throws Exception {
        Scenario plain = Scenes.valid("plain.yaml", "world: {gravity: [0, 200]}", BALL, "run: {duration: 1}");
        World a = WorldBuilder.build(plain).world();
        World b = WorldBuilder.build(plain.withNudge(1.02, WorldBuilder.defaultSpeculativeDistance())).world();
        for (int t = 0; t < 20; t++) {
            a.tick();
            b.tick();
        }
        float ya = a.getBodies()[0].getY();
        float yb = b.getBodies()[0].getY();
        assertNotEquals(ya, yb, "the nudge must reach a scene with gravity");
        assertEquals(ya, yb, Math.abs(ya) * 1e-5, "by two parts per million, not more");
    }
}
