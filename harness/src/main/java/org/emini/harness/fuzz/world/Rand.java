package org.emini.harness.fuzz.world;

import org.emini.harness.generate.SplitMix64;

/**
 * The generator's random source (SplitMix64, as the scene generators use), with draws rounded to
 * binary fractions: a generated value is a short exact decimal in a scene file and lies on the world
 * file's fixed-point grid, so writing a world out and reading it back loses nothing.
 */
final class Rand {
    /** Length step (px): 1/16, exact in a float, in a decimal and in the world file's 1/4096 grid. */
    static final float LENGTH = 1f / 16f;
    /** Angle step (rad): 1/1024, on the world file's 2⁻²⁴ grid. */
    static final float ANGLE = 1f / 1024f;
    /** Step of factors in [0, 1] (friction, elasticity, damping). */
    static final float FACTOR = 1f / 64f;

    private final SplitMix64 random;

    Rand(long seed) {
        random = new SplitMix64(seed);
    }

    /** The seed of world {@code index} of a run: the two mixed so that neighbouring worlds differ. */
    static long worldSeed(long runSeed, int index) {
        return new SplitMix64(runSeed * 0x9E3779B97F4A7C15L + index).nextLong();
    }

    double unit() {
        return random.nextDouble();
    }

    long nextLong() {
        return random.nextLong();
    }

    boolean chance(double p) {
        return unit() < p;
    }

    int between(int min, int max) {
        return min + (int) (unit() * (max - min + 1));
    }

    /** Uniform in [min, max], rounded to a multiple of step. */
    float range(double min, double max, float step) {
        return round(min + unit() * (max - min), step);
    }

    /** A length (px) in [min, max]. */
    float length(double min, double max) {
        return range(min, max, LENGTH);
    }

    /** An angle (rad) in [min, max]. */
    float angle(double min, double max) {
        return range(min, max, ANGLE);
    }

    /** A factor in [0, max]. */
    float factor(double max) {
        return range(0, max, FACTOR);
    }

    /** Log-uniform in [min, max] (for scales spanning decades), rounded to a multiple of step. */
    float logRange(double min, double max, float step) {
        return round(Math.exp(Math.log(min) + unit() * (Math.log(max) - Math.log(min))), step);
    }

    <T> T pick(T[] values) {
        return values[(int) (unit() * values.length)];
    }

    int pick(int... values) {
        return values[(int) (unit() * values.length)];
    }

    /** v rounded to a multiple of step; never −0 (a scene file writes it as 0). */
    static float round(double v, float step) {
        return (float) (Math.rint(v / step) * step) + 0f;
    }
}
