package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * A disc on a loose pin, released at 90°, swings with the large-amplitude period
 * T = 4·√(L/g)·K(sin²(θ₀/2)) of a physical pendulum (L = I_pivot/(m·d)) and keeps its amplitude.
 */
class PendulumTest {
    private static final float ARM = 100f;
    private static final float RADIUS = 5f;

    /** Times of the bob crossing below the pivot leftwards, and the amplitude at each turning point. */
    private static final class Swing {
        final List<Double> crossings = new ArrayList<>();
        final List<Double> amplitudes = new ArrayList<>();
        double closedFormPeriod;
        double worstGap;

        double period() {
            int n = crossings.size() - 1;
            return (crossings.get(n) - crossings.get(0)) / n;
        }

        double lastAmplitude() {
            return amplitudes.get(amplitudes.size() - 1);
        }
    }

    private static Swing swing(float ticksPerSecond, int iterations, boolean dynamicIterations, int periods) {
        World world = Rigs.world(ticksPerSecond, iterations);
        world.setConstraintIterationDynamic(dynamicIterations);
        Body pivot = Rigs.anchor(world, 0f, 0f);
        Body bob = new Body(ARM, 0f, Shape.createCircle(RADIUS), true);
        world.addBody(bob);
        Joint pin = Joint.atWorldPoint(pivot, bob, 0f, 0f, false);
        world.addConstraint(pin);

        Swing s = new Swing();
        double length = ARM + RADIUS * RADIUS / (2.0 * ARM);
        double g = world.getGravityY();
        s.closedFormPeriod = 4.0 * Math.sqrt(length / g) * Rigs.ellipticK(0.5);
        double dt = world.getTimestep();
        int ticks = (int) Math.ceil((periods + 0.6) * s.closedFormPeriod / dt);
        double prevX = bob.getX();
        double prevVx = 0.0;
        for (int i = 1; i <= ticks; i++) {
            world.tick();
            double x = bob.getX();
            if (prevX > 0.0 && x <= 0.0) {
                s.crossings.add((i - 1 + prevX / (prevX - x)) * dt);
            }
            double vx = bob.getVelocityX();
            if (prevVx * vx < 0.0) {
                // A turning point: the swing's angle from the vertical.
                s.amplitudes.add(Math.abs(Math.atan2(bob.getX(), bob.getY())));
            }
            prevX = x;
            prevVx = vx;
            s.worstGap = Math.max(s.worstGap, Rigs.gap(pin));
        }
        return s;
    }

    @Test
    void periodAtNinetyDegreesMatchesTheEllipticIntegralAt60Hz() {
        Swing s = swing(60f, 10, false, 20);
        double error = (s.period() - s.closedFormPeriod) / s.closedFormPeriod;
        System.out.printf("pendulum 60 Hz: T %.5f s, closed form %.5f s, error %.4f%%, pin gap ≤ %.4f px%n",
            s.period(), s.closedFormPeriod, 100 * error, s.worstGap);
        assertEquals(20, s.crossings.size() - 1);
        assertEquals(0.0, error, 0.01);
    }

    @Test
    void periodAtNinetyDegreesMatchesAtTheOriginalDefaults() {
        // 20 ticks per second, 10 iterations: the original engine's defaults.
        Swing s = swing(20f, 10, false, 20);
        double error = (s.period() - s.closedFormPeriod) / s.closedFormPeriod;
        System.out.printf("pendulum 20 Hz: T %.5f s, error %.4f%%, amplitude loss in 20 periods %.4f%%%n",
            s.period(), 100 * error, 100 * (1 - s.lastAmplitude() / (Math.PI / 2)));
        assertEquals(0.0, error, 0.01);
    }

    @Test
    void amplitudeIsKeptWithinTwoPercentOverTwentyPeriodsAt60Hz() {
        Swing s = swing(60f, 10, false, 20);
        // Two turning points per period, plus the release.
        assertTrue(s.amplitudes.size() >= 40, "turning points " + s.amplitudes.size());
        double loss = 1.0 - s.lastAmplitude() / (Math.PI / 2);
        System.out.printf("pendulum 60 Hz: amplitude after 20 periods %.6f rad (loss %.4f%%)%n", s.lastAmplitude(), 100 * loss);
        for (double a : s.amplitudes) {
            assertEquals(Math.PI / 2, a, 0.02 * Math.PI / 2);
        }
    }

    @Test
    void dynamicIterationsKeepThePeriod() {
        Swing s = swing(60f, 10, true, 10);
        double error = (s.period() - s.closedFormPeriod) / s.closedFormPeriod;
        System.out.printf("pendulum 60 Hz, dynamic iterations: error %.4f%%, amplitude loss %.4f%%%n",
            100 * error, 100 * (1 - s.lastAmplitude() / (Math.PI / 2)));
        assertEquals(0.0, error, 0.01);
        assertEquals(Math.PI / 2, s.lastAmplitude(), 0.02 * Math.PI / 2);
    }
}
