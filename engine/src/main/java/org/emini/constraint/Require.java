package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.math.EMath;

/** Argument checks that name the call and the bad value. */
final class Require {
    private Require() {
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

    /** A limit: at least 0, and positive infinity means none. */
    static float limit(String where, String what, float value) {
        if (!(value >= 0f)) {
            throw new IllegalArgumentException(where + ": " + what
                + " must be >= 0 (Float.POSITIVE_INFINITY for no limit), was " + value);
        }
        return value;
    }

    static Body inWorld(String where, String what, Body body) {
        if (body == null) {
            throw new IllegalArgumentException(where + ": " + what + " must not be null");
        }
        if (body.getWorld() == null) {
            throw new IllegalArgumentException(where + ": " + what + " (" + body
                + ") is not in a world; add the bodies to the world before constraining them");
        }
        return body;
    }
}
