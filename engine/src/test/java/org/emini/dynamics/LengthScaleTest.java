package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The length scale: a scene scaled in size and gravity by k, with the length scale set to k,
 * moves as the original scaled by k (the physics has no other length), for 0.5 px and 500 px
 * bodies; without the setting the tolerances no longer fit the bodies.
 */
class LengthScaleTest {
    /** A 10-row pyramid of 20·k px boxes under 100·k px/s², run 10 s; the boxes' positions over k. */
    private static float[] pyramid(float k, boolean scaled) {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setGravity(0f, 100f * k);
        if (scaled) {
            world.getSolverSettings().setLengthScale(k);
        }
        Body[] boxes = Scenes.pyramid(world, 10, 20f * k);
        Scenes.run(world, 10f);
        float[] out = new float[2 * boxes.length];
        for (int i = 0; i < boxes.length; i++) {
            out[2 * i] = boxes[i].getX() / k;
            out[2 * i + 1] = boxes[i].getY() / k;
        }
        return out;
    }

    private static float largestDifference(float[] a, float[] b) {
        float worst = 0f;
        for (int i = 0; i < a.length; i++) {
            worst = Math.max(worst, Math.abs(a[i] - b[i]));
        }
        return worst;
    }

    @ParameterizedTest
    @ValueSource(floats = {0.025f, 25f})
    void aScaledPyramidStandsAsTheOriginal(float k) {
        float[] original = pyramid(1f, false);
        float[] scaled = pyramid(k, true);
        // In units of the original's pixels; measured 0.018 at 0.025 and 0.022 at 25 (round-off).
        assertTrue(largestDifference(original, scaled) < 0.05f, "scaled by " + k + ": " + largestDifference(original, scaled));
    }

    @Test
    void withoutTheScaleHalfPixelBoxesDoNotBehaveAsTheOriginal() {
        float[] original = pyramid(1f, false);
        float[] unscaled = pyramid(0.025f, false);
        // Measured 0.76 px: the slop and margins of 20 px boxes on 0.5 px ones; ten times the bound above.
        assertTrue(largestDifference(original, unscaled) > 0.5f, "unscaled: " + largestDifference(original, unscaled));
    }

    @ParameterizedTest
    @ValueSource(floats = {0.025f, 1f, 25f})
    void aFastBallStopsAtAThinWallAtEveryScale(float k) {
        World world = new World();
        world.setTicksPerSecond(60);
        world.setGravity(0f, 0f);
        world.getSolverSettings().setLengthScale(k);
        world.addBody(new Body(200f * k, 0f, Shape.createRectangle(10f * k, 200f * k), false));
        Body ball = new Body(0f, 0f, Shape.createCircle(6f * k), true);
        ball.setVelocity(6000f * k, 0f);   // 100 px (scaled) a tick: ten times the wall's width
        world.addBody(ball);
        for (int t = 0; t < 60; t++) {
            world.tick();
            assertTrue(ball.getX() < 195f * k, "passed the wall at tick " + t + ": x = " + ball.getX() / k + " (scaled)");
        }
    }

    @Test
    void theScaleMultipliesEveryToleranceAndIsBounded() {
        SolverSettings s = new SolverSettings();
        float slop = s.getLinearSlop();
        float push = s.getContactPushMaxVelocity();
        s.setLengthScale(4f);
        s.setLengthScale(2f);
        assertEquals(2f * slop, s.getLinearSlop(), 1e-6f);
        assertEquals(2f * push, s.getContactPushMaxVelocity(), 1e-4f);
        assertEquals(2f, s.getLengthScale());
        assertThrows(IllegalArgumentException.class, () -> s.setLengthScale(0f));
        assertThrows(IllegalArgumentException.class, () -> s.setLengthScale(Float.NaN));
        assertThrows(IllegalArgumentException.class, () -> s.setLengthScale(1e4f));
    }
}
