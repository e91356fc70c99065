package org.emini.dynamics;

import org.emini.math.EMath;

/** Argument checks that name the call and the bad value, so bad input never becomes NaN physics. */
final class Check {
    private Check() {
    }

    static float finite(String where, String what, float value) {
        if (!EMath.isFinite(value)) {
            throw new IllegalArgumentException(where + ": " + what + " must be a finite number, was " + value);
        }
        return value;
    }

    static float nonNegative(String where, String what, float value) {
        finite(where, what, value);
        if (value < 0f) {
            throw new IllegalArgumentException(where + ": " + what + " must be >= 0, was " + value);
        }
        return value;
    }

    static float positive(String where, String what, float value) {
        finite(where, what, value);
        if (value <= 0f) {
            throw new IllegalArgumentException(where + ": " + what + " must be > 0, was " + value);
        }
        return value;
    }

    static float unit(String where, String what, float value) {
        finite(where, what, value);
        if (value < 0f || value > 1f) {
            throw new IllegalArgumentException(where + ": " + what + " must be in [0, 1], was " + value);
        }
        return value;
    }

    static <T> T notNull(String where, String what, T value) {
        if (value == null) {
            throw new IllegalArgumentException(where + ": " + what + " must not be null");
        }
        return value;
    }
}
