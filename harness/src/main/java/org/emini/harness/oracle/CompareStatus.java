package org.emini.harness.oracle;

/** How far a scene could be compared. Only ERROR makes {@code compare} fail. */
public enum CompareStatus {
    /** Both the engine and the oracle ran it. */
    COMPARED("compared"),
    /** Only the oracle ran it (the engine cannot yet). */
    ORACLE_ONLY("oracle only"),
    /** Only the engine ran it (pymunk cannot). */
    ENGINE_ONLY("engine only"),
    /** Neither ran it. */
    NEITHER("neither"),
    /** It could not be compared: an invalid scene, an oracle error, traces that do not line up. */
    ERROR("ERROR");

    private final String label;

    CompareStatus(String label) {
        this.label = label;
    }

    /** How the console, compare.json, summary.md and the dashboard write it. */
    public String label() {
        return label;
    }
}
