package org.emini.particle;

/**
 * An emitter's own random numbers: SplitMix64 (Steele, Lea and Flood, 2014), one long of state,
 * so that seeding is exact, the sequence is the same on every JVM, and drawing allocates nothing
 * (unlike {@code java.util.Random}, which also synchronises).
 */
final class ParticleRandom {
    private long state;

    ParticleRandom(long seed) {
        state = seed;
    }

    void setSeed(long seed) {
        state = seed;
    }

    long nextLong() {
        long z = state += 0x9E3779B97F4A7C15L;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /** Uniform in [0, 1): the top 24 bits, so every value is an exact float. */
    float nextFloat() {
        return (nextLong() >>> 40) * 0x1.0p-24f;
    }

    /** Uniform in [−½, ½): scaled by a deviation it gives value ± deviation/2, as the original. */
    float nextCentered() {
        return nextFloat() - 0.5f;
    }
}
