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
 * A mass on a spring with coefficient k and damping c oscillates as the closed form says:
 * x(t) = e^(−ζωt)·[x₀·cos(ω_d·t) + ζω·x₀/ω_d·sin(ω_d·t)], ω = √(k/m), ζ = c/(2√(km)),
 * ω_d = ω√(1 − ζ²).
 */
class SpringOscillationTest {
    private static final float REST = 100f;
    private static final float STRETCH = 10f;

    private static final class Oscillation {
        final List<Double> crossings = new ArrayList<>();
        double omega;
        double lastEnvelope;
        double lastEnvelopeTime;
        double zeta;
        double worstDeviation;

        double dampedPeriod() {
            return 2 * Math.PI / (omega * Math.sqrt(1 - zeta * zeta));
        }

        double measuredPeriod() {
            int n = crossings.size() - 1;
            return (crossings.get(n) - crossings.get(0)) / n;
        }

        /**
         * Decay rate of the amplitude envelope √(x² + ((v + ζωx)/ω_d)²), which is x₀·e^(−ζωt) for
         * the closed form at every instant, so no peak has to fall on a tick; closed form ζω.
         */
        double measuredDecayRate() {
            return Math.log(STRETCH / lastEnvelope) / lastEnvelopeTime;
        }
    }

    /** Mass 2 on a horizontal spring to a static anchor, gravity off, released stretched. */
    private static Oscillation oscillate(float ticksPerSecond, float k, float c, float seconds) {
        World world = Rigs.world(ticksPerSecond, 10);
        world.setGravity(0f, 0f);
        Body anchor = Rigs.anchor(world, 0f, 0f);
        Shape disc = Shape.createCircle(5f);
        disc.setMass(2f);
        Body mass = new Body(REST + STRETCH, 0f, disc, true);
        world.addBody(mass);
        Spring spring = new Spring(anchor, mass, 0f, 0f, 0f, 0f, REST);
        spring.setCoefficient(k);
        spring.setDamping(c);
        world.addConstraint(spring);

        Oscillation o = new Oscillation();
        double m = 2.0;
        o.omega = Math.sqrt(k / m);
        o.zeta = c / (2 * Math.sqrt(k * m));
        double wd = o.omega * Math.sqrt(1 - o.zeta * o.zeta);
        double dt = world.getTimestep();
        double prevX = STRETCH;
        int ticks = (int) Math.round(seconds / (float) dt);
        for (int i = 1; i <= ticks; i++) {
            world.tick();
            double t = i * dt;
            double x = mass.getX() - REST;
            double envelope = Math.exp(-o.zeta * o.omega * t);
            double exact = envelope * (STRETCH * Math.cos(wd * t) + o.zeta * o.omega * STRETCH / wd * Math.sin(wd * t));
            o.worstDeviation = Math.max(o.worstDeviation, Math.abs(x - exact));
            // Measure while the swing is well above rounding (1% of the start).
            if (envelope > 0.01) {
                if (prevX > 0 && x <= 0) {
                    o.crossings.add((i - 1 + prevX / (prevX - x)) * dt);
                }
                double v = mass.getVelocityX();
                double y = (v + o.zeta * o.omega * x) / wd;
                o.lastEnvelope = Math.sqrt(x * x + y * y);
                o.lastEnvelopeTime = t;
            }
            prevX = x;
        }
        return o;
    }

    @Test
    void undampedSpringKeepsTheClosedFormPeriodAndItsAmplitude() {
        // k = 200, m = 2: ω = 10 rad/s, T = 0.628 s; 20 periods at 60 Hz.
        Oscillation o = oscillate(60f, 200f, 0f, 13.2f);
        double error = (o.measuredPeriod() - o.dampedPeriod()) / o.dampedPeriod();
        System.out.printf("undamped spring 60 Hz: T %.5f s (closed %.5f, error %.4f%%), amplitude after %d periods %.4f px of %.1f%n",
            o.measuredPeriod(), o.dampedPeriod(), 100 * error, o.crossings.size() - 1, o.lastEnvelope, STRETCH);
        assertTrue(o.crossings.size() > 20);
        assertEquals(0.0, error, 0.02);
        assertEquals(STRETCH, o.lastEnvelope, 0.02 * STRETCH);
    }

    @Test
    void dampedSpringMatchesTheClosedFormFrequencyAndDecay() {
        // k = 200, c = 2, m = 2: ζ = 0.05, decay rate ζω = 0.5 /s.
        Oscillation o = oscillate(60f, 200f, 2f, 10f);
        double periodError = (o.measuredPeriod() - o.dampedPeriod()) / o.dampedPeriod();
        double rate = o.zeta * o.omega;
        double decayError = (o.measuredDecayRate() - rate) / rate;
        System.out.printf("damped spring 60 Hz: T_d %.5f s (error %.4f%%), decay %.5f /s (closed %.5f, error %.3f%%), "
            + "largest deviation from x(t) %.4f px%n",
            o.measuredPeriod(), 100 * periodError, o.measuredDecayRate(), rate, 100 * decayError, o.worstDeviation);
        assertEquals(0.0, periodError, 0.02);
        assertEquals(0.0, decayError, 0.02);
        assertTrue(o.worstDeviation < 0.02 * STRETCH, "deviation " + o.worstDeviation);
    }

    @Test
    void dampedSpringMatchesAtTheOriginalDefaults() {
        Oscillation o = oscillate(20f, 200f, 2f, 10f);
        double periodError = (o.measuredPeriod() - o.dampedPeriod()) / o.dampedPeriod();
        double rate = o.zeta * o.omega;
        double decayError = (o.measuredDecayRate() - rate) / rate;
        System.out.printf("damped spring 20 Hz: period error %.4f%%, decay error %.3f%%, deviation %.4f px%n",
            100 * periodError, 100 * decayError, o.worstDeviation);
        assertEquals(0.0, periodError, 0.02);
        assertEquals(0.0, decayError, 0.02);
    }

    @Test
    void springGivenAsFrequencyAndRatioBehavesLikeTheEquivalentCoefficients() {
        // ω = 10 rad/s and ζ = 0.05 on mass 2 are k = 200 and c = 2.
        World a = Rigs.world(60f, 10);
        World b = Rigs.world(60f, 10);
        Body[] ends = new Body[2];
        Spring[] springs = new Spring[2];
        World[] worlds = {a, b};
        for (int i = 0; i < 2; i++) {
            worlds[i].setGravity(0f, 0f);
            Body anchor = Rigs.anchor(worlds[i], 0f, 0f);
            Shape disc = Shape.createCircle(5f);
            disc.setMass(2f);
            ends[i] = new Body(REST + STRETCH, 0f, disc, true);
            worlds[i].addBody(ends[i]);
            springs[i] = new Spring(anchor, ends[i], 0f, 0f, 0f, 0f, REST);
            worlds[i].addConstraint(springs[i]);
        }
        springs[0].setCoefficient(200f);
        springs[0].setDamping(2f);
        springs[1].setFrequency((float) (10 / (2 * Math.PI)), 0.05f);
        for (int t = 0; t < 300; t++) {
            a.tick();
            b.tick();
            assertEquals(ends[0].getX(), ends[1].getX(), 1e-3, "tick " + t);
        }
    }
}
