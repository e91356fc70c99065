package org.emini.internal;

import org.emini.math.EMath;

/**
 * Argument checks that name the call and the bad value, so bad input never becomes NaN physics.
 * Shared by the engine's packages; not part of the API. Each check takes {@code where} (the call,
 * e.g. {@code "Body.setMass"}) and {@code what} (the argument's name) for its message, and returns
 * the value when it passes.
 */
public final class Check {
    private Check() {
    }

    /**
     * @param where the call, for the message
     * @param what the argument, for the message
     * @param value the value
     * @return value, when it is finite
     */
    public static float finite(String where, String what, float value) {
        if (!EMath.isFinite(value)) {
            throw new IllegalArgumentException(where + ": " + what + " must be a finite number, was " + value);
        }
        return value;
    }

    /**
     * @param where the call, for the message
     * @param what the argument, for the message
     * @param value the value
     * @return value, when it is finite and at least 0
     */
    public static float nonNegative(String where, String what, float value) {
        finite(where, what, value);
        if (value < 0f) {
            throw new IllegalArgumentException(where + ": " + what + " must be >= 0, was " + value);
        }
        return value;
    }

    /**
     * @param where the call, for the message
     * @param what the argument, for the message
     * @param value the value
     * @return value, when it is finite and above 0
     */
    public static float positive(String where, String what, float value) {
        finite(where, what, value);
        if (value <= 0f) {
            throw new IllegalArgumentException(where + ": " + what + " must be > 0, was " + value);
        }
        return value;
    }

    /**
     * @param where the call, for the message
     * @param what the argument, for the message
     * @param value the value
     * @return value, when it is in [0, 1]
     */
    public static float unit(String where, String what, float value) {
        finite(where, what, value);
        if (value < 0f || value > 1f) {
            throw new IllegalArgumentException(where + ": " + what + " must be in [0, 1], was " + value);
        }
        return value;
    }

    /**
     * @param where the call, for the message
     * @param what the argument, for the message
     * @param value the value
     * @param min the smallest value allowed
     * @param max the largest value allowed
     * @return value, when it is in [min, max]
     */
    public static float within(String where, String what, float value, float min, float max) {
        if (!(value >= min && value <= max)) {
            throw new IllegalArgumentException(where + ": " + what + " must be in [" + min + ", " + max + "], was " + value);
        }
        return value;
    }

    /**
     * @param where the call, for the message
     * @param what the argument, for the message
     * @param value the value
     * @return value, a limit: at least 0, where positive infinity means no limit
     */
    public static float limit(String where, String what, float value) {
        if (!(value >= 0f)) {
            throw new IllegalArgumentException(where + ": " + what
                + " must be >= 0 (Float.POSITIVE_INFINITY for no limit), was " + value);
        }
        return value;
    }

    /**
     * @param <T> the value's type
     * @param where the call, for the message
     * @param what the argument, for the message
     * @param value the value
     * @return value, when it is not null
     */
    public static <T> T notNull(String where, String what, T value) {
        if (value == null) {
            throw new IllegalArgumentException(where + ": " + what + " must not be null");
        }
        return value;
    }
}
