package org.emini.harness.fuzz.world;

/**
 * A violation found in a world.
 *
 * @param kind what was violated
 * @param tick the tick after which it was seen (counted from 0), or -1 for a whole-run relation
 * @param message what was measured against which bound, naming the bodies by recipe id
 */
public record Violation(ViolationKind kind, int tick, String message) {
    @Override
    public String toString() {
        return kind.label() + (tick >= 0 ? " at tick " + tick : "") + ": " + message;
    }
}
