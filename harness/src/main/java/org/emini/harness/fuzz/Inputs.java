package org.emini.harness.fuzz;

import java.util.SplittableRandom;

/** Seeded randomness per input: input i of seed S is the same on every machine, whatever ran before it. */
final class Inputs {
    private Inputs() {
    }

    /** The generator of one input. */
    static SplittableRandom random(long seed, long index) {
        long z = seed + 0x9E3779B97F4A7C15L * (index + 1);
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return new SplittableRandom(z ^ (z >>> 31));
    }

    /** One of the values. */
    @SafeVarargs
    static <T> T pick(SplittableRandom r, T... values) {
        return values[r.nextInt(values.length)];
    }
}
