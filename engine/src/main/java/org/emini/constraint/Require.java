package org.emini.constraint;

import org.emini.dynamics.Body;

/** The check every constraint makes of its bodies (number checks: {@link org.emini.internal.Check}). */
final class Require {
    private Require() {
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
