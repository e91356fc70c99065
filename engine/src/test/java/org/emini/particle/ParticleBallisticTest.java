package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import org.emini.world.World;
import org.emini.math.EMath;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Free particles follow the parabola of gravity × gravity factor exactly: the update
 * x += v·dt + ½·g·dt², v += g·dt has no error for constant acceleration, so x(t) = x0 + v0·t +
 * ½·g·t² whatever the tick rate. Damping multiplies the velocity by q = 1 − d after each tick.
 */
class ParticleBallisticTest {
    /** One particle emitted now from (x0, y0) at the given speed and angle. */
    private static ParticleEmitter one(World world, float x0, float y0, float speed, float angle, float gravityFactor) {
        ParticleEmitter e = ParticleScenes.one(world, x0, y0, speed * EMath.cos(angle), speed * EMath.sin(angle));
        e.setGravityFactor(gravityFactor);
        assertEquals(1, e.getParticleCount());
        return e;
    }

    @ParameterizedTest
    @CsvSource({"20, 1, 1", "20, 0.5, 1", "60, -0.3, 1", "20, 2, 0.5", "30, 0, 1", "20, 1.5, 0.25"})
    void freeParticleFollowsTheParabolaOfScaledGravity(float ticksPerSecond, float factor, float gravityScale) {
        World world = new World();
        world.setTicksPerSecond(ticksPerSecond);
        world.setGravity(20f * gravityScale, 100f * gravityScale);
        float angle = -EMath.PI / 3f;
        ParticleEmitter e = one(world, 10f, -20f, 80f, angle, factor);
        double vx0 = 80.0 * Math.cos(angle);
        double vy0 = 80.0 * Math.sin(angle);
        double gx = 20.0 * gravityScale * factor;
        double gy = 100.0 * gravityScale * factor;
        int ticks = (int) Math.round(3f * ticksPerSecond);
        for (int n = 1; n <= ticks; n++) {
            world.tick();
            double t = n * (double) world.getTimestep();
            assertEquals(10.0 + vx0 * t + 0.5 * gx * t * t, e.getX(0), 2e-3, "x at tick " + n);
            assertEquals(-20.0 + vy0 * t + 0.5 * gy * t * t, e.getY(0), 2e-3, "y at tick " + n);
            assertEquals(vx0 + gx * t, e.getVelocityX(0), 1e-3, "vx at tick " + n);
            assertEquals(vy0 + gy * t, e.getVelocityY(0), 1e-3, "vy at tick " + n);
            assertEquals(t, e.getAge(0), 1e-5);
        }
    }

    @Test
    void pathDoesNotDependOnTheTickRate() {
        float[] xs = new float[3];
        float[] ys = new float[3];
        int[] rates = {10, 20, 120};
        for (int k = 0; k < 3; k++) {
            World world = new World();
            world.setTicksPerSecond(rates[k]);
            ParticleEmitter e = one(world, 0f, 0f, 150f, -1f, 0.7f);
            ParticleScenes.run(world, 2 * rates[k]);
            xs[k] = e.getX(0);
            ys[k] = e.getY(0);
        }
        assertEquals(xs[0], xs[1], 2e-3);
        assertEquals(xs[0], xs[2], 2e-3);
        assertEquals(ys[0], ys[1], 2e-3);
        assertEquals(ys[0], ys[2], 2e-3);
    }

    /**
     * With q = 1 − d: v_n = qⁿ·v0 + g·h·q·(1 − qⁿ)/(1 − q), x_n = x0 + h·Σ v_k + n·½·g·h²,
     * Σ_{k<n} v_k = v0·(1 − qⁿ)/(1 − q) + g·h·q/(1 − q)·(n − (1 − qⁿ)/(1 − q)); the terminal
     * velocity is g·h·q/(1 − q).
     */
    @Test
    void dampingFollowsTheGeometricClosedForm() {
        World world = new World();
        ParticleEmitter e = one(world, 0f, 0f, 60f, 0f, 1f);
        e.setDamping(0.1f);
        double q = 0.9;
        double h = world.getTimestep();
        double g = 100.0;
        for (int n = 1; n <= 100; n++) {
            world.tick();
            double qn = Math.pow(q, n);
            double geometric = (1 - qn) / (1 - q);
            double vy = g * h * q * geometric;
            double sumVy = g * h * q / (1 - q) * (n - geometric);
            assertEquals(60.0 * qn, e.getVelocityX(0), 1e-3, "vx at tick " + n);
            assertEquals(vy, e.getVelocityY(0), 1e-3, "vy at tick " + n);
            assertEquals(h * 60.0 * geometric, e.getX(0), 2e-3, "x at tick " + n);
            assertEquals(h * sumVy + n * 0.5 * g * h * h, e.getY(0), 2e-3, "y at tick " + n);
        }
        assertEquals(g * h * q / (1 - q), e.getVelocityY(0), 1e-2, "terminal velocity");
    }

    /**
     * Births are spread over the tick: at 200 particles/s and 100 px/s along +x without gravity,
     * the particles of one tick lie 0.5 px apart, as a continuous stream, each at 100 px/s × its
     * age from the emitter.
     */
    @Test
    void aSteadyEmitterMakesAContinuousStream() {
        World world = new World();
        world.setGravity(0f, 0f);
        ParticleEmitter e = new ParticleEmitter(1000);
        e.setCreationRate(200f, 0f);
        e.setSpeed(100f, 0f);
        e.setEmitPoint(5f, 7f);
        world.addParticleEmitter(e);
        ParticleScenes.run(world, 7);
        int n = e.getParticleCount();
        assertEquals(70, n);
        float[] xs = new float[n];
        for (int i = 0; i < n; i++) {
            assertEquals(5f + 100f * e.getAge(i), e.getX(i), 1e-3);
            assertEquals(7f, e.getY(i), 0f);
            xs[i] = e.getX(i);
        }
        Arrays.sort(xs);
        for (int i = 1; i < n; i++) {
            assertEquals(0.5, xs[i] - xs[i - 1], 1e-3, "gap " + i);
        }
    }
}
