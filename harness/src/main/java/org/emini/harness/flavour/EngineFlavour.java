package org.emini.harness.flavour;

/**
 * Which engine flavour this build of the harness drives. The double flavour's harness is generated from
 * this source by the engine's flavour rules (engine-double/README.md), which turn {@code Float} into
 * {@code Double}: so {@link #DOUBLE} is false in the float build and true in the double one.
 */
public final class EngineFlavour {
    /** True in the harness built for the double-precision engine. */
    public static final boolean DOUBLE = Float.SIZE == Double.SIZE;
    /** The flavour's name, "float" or "double". */
    public static final String NAME = DOUBLE ? "double" : "float";
    /** The engine's name in sweep points: "emini" for the float engine, "emini-double" for the double flavour. */
    public static final String ENGINE = DOUBLE ? "emini-double" : "emini";

    private EngineFlavour() {
    }
}
