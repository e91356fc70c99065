package org.emini.harness.fuzz.world;

import java.util.regex.Pattern;

/**
 * What a throwing tick means. A documented clear error is an IllegalStateException or
 * IllegalArgumentException whose message names the public call that refused (World.tick: ...,
 * Body.applyForce: ...), as CONTRIBUTING.md asks of bad input; World.tick's "became non-finite" is
 * the documented end of a world whose values overflowed. Anything else (a NullPointerException, an
 * index out of bounds, a message from an internal class) is an engine defect.
 */
final class TickFailure {
    private static final Pattern NAMED_CALL = Pattern.compile("^[A-Z][A-Za-z0-9]*(\\.[a-z][A-Za-z0-9]*)?[:(]");

    private TickFailure() {
    }

    static boolean clear(Throwable e) {
        return (e instanceof IllegalStateException || e instanceof IllegalArgumentException)
                && e.getMessage() != null && NAMED_CALL.matcher(e.getMessage()).find();
    }

    static boolean nonFinite(Throwable e) {
        return clear(e) && e.getMessage().contains("non-finite");
    }

    /** The exception with the engine frames that threw it. */
    static String describe(Throwable e) {
        StringBuilder b = new StringBuilder(e.getClass().getName()).append(": ").append(e.getMessage());
        int shown = 0;
        for (StackTraceElement f : e.getStackTrace()) {
            if (f.getClassName().startsWith("org.emini.") && !f.getClassName().startsWith("org.emini.harness") && shown < 4) {
                b.append(shown == 0 ? " at " : " < ").append(f.getClassName().substring(10)).append('.')
                        .append(f.getMethodName()).append(':').append(f.getLineNumber());
                shown++;
            }
        }
        return b.toString();
    }

    /** The violation a throwing tick is in a world where a clear error is not expected. */
    static Violation violation(Throwable e, int tick) {
        return new Violation(nonFinite(e) ? ViolationKind.NON_FINITE : ViolationKind.EXCEPTION, tick, describe(e));
    }
}
