package org.emini.harness.oracle;

/** Which side of a row is closer to the truth (scenarios/README.md, Comparison with the oracle). */
public enum Closer {
    /** The engine's error is the smaller. */
    ENGINE("engine"),
    /** The oracle's (pymunk's) error is the smaller. */
    ORACLE("oracle"),
    /** Both errors are within float noise or 5% of each other. */
    TIE("tie"),
    /** Not judged: the row has no reference, a side is missing, or the oracle's run is incomplete. */
    NONE("-");

    private final String label;

    Closer(String label) {
        this.label = label;
    }

    /** How compare.json and the dashboard write it. */
    public String label() {
        return label;
    }
}
