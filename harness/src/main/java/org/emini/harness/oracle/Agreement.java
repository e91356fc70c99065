package org.emini.harness.oracle;

/** Whether a row's engine and oracle figures agree (scenarios/README.md, Comparison with the oracle). */
public enum Agreement {
    /** |engine − oracle| is within the tolerance. */
    AGREE("agree"),
    /** It is not (a NaN difference differs). */
    DIFFER("differ"),
    /**
     * Not judged by agreement: pymunk left out an element that moves bodies, or the row has a reference
     * in a continuousCollision scene (judged against the truth only).
     */
    NOT_JUDGED("n/a"),
    /** A side did not run. */
    NONE("-");

    private final String label;

    Agreement(String label) {
        this.label = label;
    }

    /** How compare.json, summary.md and the dashboard write it. */
    public String label() {
        return label;
    }
}
