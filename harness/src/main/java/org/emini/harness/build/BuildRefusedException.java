package org.emini.harness.build;

import org.emini.harness.load.JsonPath;

/**
 * The engine refused a value of the scene (a non-convex polygon, 1e39 in a float, a joint between a body
 * and itself): its {@code IllegalArgumentException}, with the place in the scene that gave the value.
 * {@code validate} builds every scene's world, so it refuses what the builder would, at that place.
 */
public final class BuildRefusedException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    private final transient JsonPath path;

    BuildRefusedException(JsonPath path, String message, Throwable engine) {
        super(message, engine);
        this.path = path;
    }

    /** Where the refused value is written. */
    public JsonPath path() {
        return path;
    }
}
