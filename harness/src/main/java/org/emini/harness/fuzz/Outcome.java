package org.emini.harness.fuzz;

/** What became of one fuzz input. Everything but {@link #CLEAN} and {@link #ACCEPTED} is a failure. */
public enum Outcome {
    /** Refused with a message naming the place and the problem. */
    CLEAN("clean error"),
    /** Read, built and ticked a few times with a finite state. */
    ACCEPTED("accepted"),
    /** Refused, but without saying where (a file:line, a $.path, a byte offset, the call). */
    UNLOCATED("unlocated error"),
    /** Any other exception or Error (an OutOfMemoryError included), or the worker died. */
    CRASH("crash"),
    /** Over the time limit per input. */
    HANG("hang"),
    /** Accepted, but the built world or its state after a few ticks holds NaN or infinity. */
    SILENT_NAN("silent NaN");

    private final String label;

    Outcome(String label) {
        this.label = label;
    }

    /** The category's name in the summary. */
    public String label() {
        return label;
    }

    /** Whether it makes the fuzz run fail. */
    public boolean failure() {
        return this != CLEAN && this != ACCEPTED;
    }
}
