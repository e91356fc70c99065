package org.emini.harness.fuzz.world;

/** What a world violated: an invariant checked every tick, or a metamorphic relation. */
public enum ViolationKind {
    /** The recipe did not build (a generator error, or the engine refused a valid value). */
    BUILD("build"),
    /** tick() threw something other than a documented clear error. */
    EXCEPTION("exception"),
    /** A body pose or velocity, a particle or a constraint force became NaN or infinite. */
    NON_FINITE("non-finite state"),
    /** A world without energy sources gained energy beyond the bound. */
    ENERGY("energy created"),
    /** A dynamic body's centre passed into or through a static body or a landscape segment. */
    PASS_THROUGH("pass-through"),
    /** Two touching bodies overlap beyond the bound after settling. */
    OVERLAP("overlap"),
    /** Ticks kept allocating after warm-up. */
    ALLOCATION("allocation"),
    /** Two runs of the same recipe differ. */
    NONDETERMINISM("nondeterminism"),
    /** A simulation area holding every body changed the motion. */
    SIMULATION_AREA("relation: simulation area"),
    /** An idle feature changed the motion. */
    IDLE_FEATURES("relation: idle features"),
    /** Dynamic iterations disagree with fixed iterations. */
    ITERATION_MODE("relation: dynamic iterations"),
    /** The mirrored world does not move as the mirror image. */
    MIRROR("relation: mirror"),
    /** The world moved far from the origin moves differently. */
    TRANSLATION("relation: translation"),
    /** Halving the timestep does not approach the finer runs. */
    CONVERGENCE("relation: convergence"),
    /** The scene as YAML, JSON or a world file builds another world. */
    FORMAT("relation: file formats"),
    /** The bullet flag changed a world where nothing is fast. */
    BULLET("relation: bullet flag");

    private final String label;

    ViolationKind(String label) {
        this.label = label;
    }

    /** How reports name it. */
    public String label() {
        return label;
    }
}
