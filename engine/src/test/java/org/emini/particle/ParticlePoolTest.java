package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * The pool grows with its particles up to its maximum, and a tick's emission is bounded by the pool
 * and by the longest lifetime, whatever the timestep and rate.
 */
class ParticlePoolTest {
    private static long bytesAllocatedBy(Runnable work) {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(thread);
        work.run();
        return threads.getThreadAllocatedBytes(thread) - before;
    }

    @Test
    void aLargePoolCostsMemoryOnlyForTheParticlesThatLive() {
        ParticleEmitter[] made = new ParticleEmitter[1];
        // A full pool of the largest size would be 32 MiB; an empty one is a few small arrays.
        long bytes = bytesAllocatedBy(() -> made[0] = new ParticleEmitter(ParticleEmitter.MAX_PARTICLES));
        assertTrue(bytes < 64 * 1024, bytes + " bytes for an empty pool");
        ParticleEmitter e = made[0];
        assertEquals(ParticleEmitter.MAX_PARTICLES, e.getMaxParticles());
        assertEquals(5000, e.emit(5000));
        assertEquals(5000, e.getParticleCount());
        e.setMaxParticles(3000);
        assertEquals(3000, e.getParticleCount());
        assertEquals(3000, e.getMaxParticles());
        assertEquals(0, e.emit(1));
    }

    @Test
    void aTimestepOfAThousandMillionSecondsEmitsTheLastLifetimeOnly() {
        World world = new World();
        world.setGravity(0f, 0f);
        world.setTimestep(1e9f);
        ParticleEmitter e = new ParticleEmitter(100);
        e.setCreationRate(20f, 0f);
        e.setLifetime(2f, 0f);
        world.addParticleEmitter(e);
        world.tick();
        // Rate × lifetime are alive at the end of any tick longer than the lifetime.
        assertEquals(40, e.getParticleCount());
        for (int i = 0; i < e.getParticleCount(); i++) {
            assertTrue(e.getAge(i) < 2f, "age " + e.getAge(i));
            assertTrue(Math.abs(e.getX(i)) <= 20f, "x " + e.getX(i));
        }
    }

    @Test
    void aRateBeyondThePoolFillsItAndNoMore() {
        World world = new World();
        ParticleEmitter e = new ParticleEmitter(100);
        e.setCreationRate(ParticleEmitter.MAX_RATE, 0f);
        e.setLifetime(1f, 2f);
        world.addParticleEmitter(e);
        world.tick();
        assertTrue(e.getParticleCount() > 0 && e.getParticleCount() <= 100, "particles " + e.getParticleCount());
    }
}
