package org.emini.harness.run;

/** The verdict on a scene. Only FAIL and ERROR make a run fail. */
public enum Status {
    /** Every expectation holds. */
    PASS("pass"),
    /** Only expectations marked as known failures fail (or the scene itself is marked). */
    KNOWN_FAILURE("known"),
    /** An expectation not marked as known fails: a regression. */
    FAIL("FAIL"),
    /** The scene uses an element the engine does not offer yet. */
    UNSUPPORTED("unsupported"),
    /** The scene is invalid or the run threw. */
    ERROR("ERROR");

    private final String label;

    Status(String label) {
        this.label = label;
    }

    /** How reports print it. */
    public String label() {
        return label;
    }

    /** Whether this status fails the run. */
    public boolean failsRun() {
        return this == FAIL || this == ERROR;
    }
}
