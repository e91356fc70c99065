package org.emini.harness.cli;

import java.util.List;
import org.emini.harness.sweep.SweepGrid;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;

/** Checks of option values that picocli's types cannot state; a bad value is a usage error (exit 2). */
final class Options {
    private Options() {
    }

    /** The value when it is at least {@code min}; otherwise a usage error naming the option. */
    static int atLeast(CommandSpec spec, String option, int value, int min) {
        if (value < min) {
            throw new ParameterException(spec.commandLine(), option + " must be at least " + min + ", was " + value);
        }
        return value;
    }

    /** The value when it is {@code min} to {@code max}; otherwise a usage error naming the option. */
    static int within(CommandSpec spec, String option, int value, int min, int max) {
        if (value < min || value > max) {
            throw new ParameterException(spec.commandLine(), option + " must be " + min + " to " + max + ", was " + value);
        }
        return value;
    }

    /** A usage error unless the condition holds. */
    static void require(CommandSpec spec, boolean condition, String message) {
        if (!condition) {
            throw new ParameterException(spec.commandLine(), message);
        }
    }

    /** Tick rates a sweep or a stability map may use: a timestep of at least a microsecond. */
    static final int MAX_RATE = 1_000_000;

    /** {@code --rates FROM..TO} and the iteration counts as a grid; a malformed value is a usage error. */
    static SweepGrid grid(CommandSpec spec, String rates, List<Integer> iterations) {
        String[] r = rates.split("\\.\\.");
        int from;
        int to;
        try {
            from = Integer.parseInt(r[0].trim());
            to = Integer.parseInt(r[r.length - 1].trim());
        } catch (NumberFormatException e) {
            throw new ParameterException(spec.commandLine(), "--rates " + rates + ": FROM..TO in ticks per second");
        }
        require(spec, r.length <= 2 && from >= 1 && to >= from && to <= MAX_RATE,
                "--rates " + rates + ": need 1 <= FROM <= TO <= " + MAX_RATE);
        for (int n : iterations) {
            require(spec, n >= 1 && n <= 1000, "--iterations " + n + ": need 1 to 1000 (the engine's range)");
        }
        return SweepGrid.of(from, to, iterations);
    }
}
