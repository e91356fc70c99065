package org.emini.harness.fuzz;

import java.nio.charset.StandardCharsets;

/**
 * A checker that does what its input says (hang, die, run out of memory, answer), to test that the
 * sandbox classifies a worker's misbehaviour and carries on with a fresh worker.
 */
public final class MisbehavingChecker implements Checker {
    /** Kept so the allocation cannot be optimised away. */
    static volatile Object sink;

    @Override
    public Verdict check(byte[] input) {
        switch (new String(input, StandardCharsets.UTF_8)) {
            case "hang" -> {
                while (!Thread.currentThread().isInterrupted()) {
                    Thread.onSpinWait();
                }
                return Verdict.accepted("interrupted");
            }
            case "die" -> {
                Runtime.getRuntime().halt(7);
                return null;
            }
            case "oom" -> {
                java.util.List<long[]> hog = new java.util.ArrayList<>();
                while (true) {
                    hog.add(new long[1 << 20]);
                    sink = hog;
                }
            }
            default -> {
                return Verdict.clean("echo", new String(input, StandardCharsets.UTF_8));
            }
        }
    }
}
