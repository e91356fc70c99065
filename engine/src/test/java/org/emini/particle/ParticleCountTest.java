package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Emission follows the rate and the lifetime: births are continuous at the rate, so in steady
 * state the live count is rate × lifetime (Little's law), and it never passes the maximum.
 */
class ParticleCountTest {
    private static World weightless() {
        World world = new World();
        world.setGravity(0f, 0f);
        return world;
    }

    @ParameterizedTest
    @CsvSource({"200, 3, 20", "20, 2, 20", "7.3, 5, 20", "1000, 0.5, 60", "45, 1.13, 30"})
    void steadyStateCountIsRateTimesLifetimeWithinOneParticle(float rate, float lifetime, float ticksPerSecond) {
        World world = weightless();
        world.setTicksPerSecond(ticksPerSecond);
        ParticleEmitter e = ParticleScenes.spray(100_000, rate, lifetime, 50f, 0f);
        world.addParticleEmitter(e);
        int warmUp = (int) Math.ceil(lifetime * ticksPerSecond) + 2;
        ParticleScenes.run(world, warmUp);
        for (int t = 0; t < 200; t++) {
            world.tick();
            assertEquals(rate * lifetime, e.getParticleCount(), 1.0, "tick " + t);
        }
    }

    @Test
    void emittedCountFollowsTheRateExactlyOverTime() {
        World world = weightless();
        ParticleEmitter e = ParticleScenes.spray(100_000, 7.3f, 1000f, 10f, 0f);
        world.addParticleEmitter(e);
        for (int t = 1; t <= 400; t++) {
            world.tick();
            // The fraction of a particle owed carries over: count = floor(rate × time), never drifts. Where
            // rate × time is a whole number, round-off may land the sum just below it (the double flavour).
            double owed = 7.3 * t * world.getTimestep();
            int count = e.getParticleCount();
            assertTrue(count == Math.floor(owed + 1e-4) || count == Math.floor(owed - 1e-4), "tick " + t + ": " + count);
        }
    }

    /**
     * With a rate of 200 ± 50 /s drawn per tick and a lifetime of 3 ± 1 s drawn per particle
     * (full widths 100 and 2), the mean count is still 200 × 3 = 600; its spread is about 20
     * (rate noise summed over the 60 ticks of a lifetime, plus the lifetime's). The long-run mean
     * must be within 2 % (over 3 standard errors of the mean) and every tick within 15 %.
     */
    @Test
    void meanCountIsRateTimesMeanLifetimeWithDeviations() {
        World world = weightless();
        ParticleEmitter e = ParticleScenes.spray(100_000, 200f, 3f, 50f, 20f);
        e.setCreationRate(200f, 100f);
        e.setLifetime(3f, 2f);
        e.setSeed(12345L);
        world.addParticleEmitter(e);
        ParticleScenes.run(world, 100);
        double sum = 0;
        int ticks = 2000;
        for (int t = 0; t < ticks; t++) {
            world.tick();
            int n = e.getParticleCount();
            assertEquals(600.0, n, 90.0, "tick " + t);
            sum += n;
        }
        assertEquals(600.0, sum / ticks, 12.0);
    }

    @Test
    void lifetimesSpreadUniformlyOverTheDeviation() {
        World world = weightless();
        ParticleEmitter e = ParticleScenes.spray(100_000, 2000f, 3f, 0f, 0f);
        e.setLifetime(3f, 2f);
        world.addParticleEmitter(e);
        world.tick();
        float lo = Float.MAX_VALUE;
        float hi = -Float.MAX_VALUE;
        double sum = 0;
        for (int i = 0; i < e.getParticleCount(); i++) {
            float l = e.getParticleLifetime(i);
            lo = Math.min(lo, l);
            hi = Math.max(hi, l);
            sum += l;
        }
        assertEquals(100, e.getParticleCount());
        assertTrue(lo >= 2f && hi < 4f, lo + " .. " + hi);
        assertEquals(3.0, sum / e.getParticleCount(), 0.15);
    }

    @Test
    void countStopsAtTheMaximumAndEmissionResumesWhenParticlesDie() {
        World world = weightless();
        ParticleEmitter e = ParticleScenes.spray(250, 1000f, 1f, 10f, 0f);
        world.addParticleEmitter(e);
        int full = 0;
        for (int t = 0; t < 200; t++) {
            world.tick();
            assertTrue(e.getParticleCount() <= 250, "tick " + t + ": " + e.getParticleCount());
            if (e.getParticleCount() == 250) {
                full++;
            }
        }
        // Full from the fifth tick on (50 births a tick); the dead are replaced at once.
        assertEquals(200 - 4, full);
        float oldest = 0f;
        for (int i = 0; i < e.getParticleCount(); i++) {
            oldest = Math.max(oldest, e.getAge(i));
        }
        assertTrue(oldest < 1f, "no particle outlives its lifetime: " + oldest);
    }

    @Test
    void burstsAddToTheRateAndRespectTheMaximum() {
        World world = weightless();
        ParticleEmitter e = ParticleScenes.spray(100, 0f, 1f, 10f, 0f);
        world.addParticleEmitter(e);
        assertEquals(60, e.emit(60));
        assertEquals(40, e.emit(60));
        assertEquals(100, e.getParticleCount());
        ParticleScenes.run(world, 19);
        assertEquals(100, e.getParticleCount());
        world.tick();
        assertEquals(0, e.getParticleCount(), "all die when their age reaches the 1 s lifetime");
    }

    @Test
    void shrinkingThePoolDropsTheSurplusAndGrowingKeepsTheParticles() {
        World world = weightless();
        ParticleEmitter e = ParticleScenes.spray(100, 0f, 10f, 10f, 0f);
        world.addParticleEmitter(e);
        e.emit(80);
        world.tick();
        float x5 = e.getX(5);
        e.setMaxParticles(50);
        assertEquals(50, e.getParticleCount());
        e.setMaxParticles(200);
        assertEquals(50, e.getParticleCount());
        assertEquals(x5, e.getX(5));
        assertEquals(150, e.emit(1000));
    }

    @ParameterizedTest
    @CsvSource({"3, 20", "2, 60", "1.1, 30"})
    void aParticleDiesInTheTickItsAgeReachesItsLifetime(float lifetime, float ticksPerSecond) {
        // Summing the timestep in float falls short (60 × 0.05 = 2.9999983): that must not buy a tick.
        World world = weightless();
        world.setTicksPerSecond(ticksPerSecond);
        ParticleEmitter e = ParticleScenes.spray(100, 0.001f, lifetime, 10f, 0f);
        e.setLifetime(lifetime, 0f);
        world.addParticleEmitter(e);
        e.emit(10);
        int ticks = (int) Math.round(lifetime * ticksPerSecond);
        ParticleScenes.run(world, ticks - 1);
        assertEquals(10, e.getParticleCount(), "alive one tick before their lifetime");
        world.tick();
        assertEquals(0, e.getParticleCount(), "gone in tick " + ticks);
    }
}
