package org.emini.harness.generate;

/**
 * The random numbers of the rain generator: SplitMix64 (Steele, Lea, Flood 2014), chosen because it is
 * five lines in any language, so the Python oracle (oracle-py/) rebuilds exactly the same scene from the
 * same seed. The algorithm is spelled out in scenarios/README.md; do not replace it with
 * java.util.Random.
 */
public final class SplitMix64 {
    private long state;

    /** Starts the sequence at a seed. */
    public SplitMix64(long seed) {
        state = seed;
    }

    /** The next 64 random bits. */
    public long nextLong() {
        state += 0x9E3779B97F4A7C15L;
        long z = state;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /** A uniform double in [0, 1): the top 53 bits of {@link #nextLong()} times 2⁻⁵³. */
    public double nextDouble() {
        return (nextLong() >>> 11) * 0x1.0p-53;
    }
}
