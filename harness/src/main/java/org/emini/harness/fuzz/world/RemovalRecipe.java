package org.emini.harness.fuzz.world;

/**
 * A body removed while a tick runs: from the event listener (the world gets an always-true position
 * event) or from a custom constraint's {@code prepare}. The engine documents that a listener must
 * not remove bodies; the fuzzer accepts a clear error (an IllegalStateException naming the call) or
 * a tick that copes, and reports anything else.
 */
public final class RemovalRecipe {
    /** Where the removal happens. */
    public enum Via {
        /** In {@code PhysicsEventListener.eventTriggered}. */
        listener,
        /** In {@code Constraint.prepare}. */
        constraint
    }

    /** Id as generated. */
    public int id;
    /** The removed body's id. */
    public int body;
    /** The tick (counted from 0) during which it is removed. */
    public int tick;
    /** Where. */
    public Via via = Via.listener;
}
