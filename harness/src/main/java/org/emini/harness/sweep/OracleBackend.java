package org.emini.harness.sweep;

/**
 * The pymunk oracle's side of a sweep. PENDING: the oracle (issue 6, branch {@code oracle}) is not on
 * this branch yet. Once it lands this backend writes the variants to files, runs them with
 * {@code python -m emini_oracle run} and reads the traces back; until then it reports itself
 * unavailable and sweeps, plots and maps show the oracle as pending.
 */
public final class OracleBackend implements SweepBackend {
    /** Why the oracle does not run yet. */
    public static final String PENDING = "pending: the pymunk oracle (issue 6) is not merged yet";

    @Override
    public String name() {
        return "pymunk";
    }

    @Override
    public String unavailable() {
        return PENDING;
    }

    @Override
    public Measured run(String sceneId, String variantText, int repeats) {
        return new Measured("unsupported", PENDING, null, Double.NaN, Double.NaN);
    }
}
