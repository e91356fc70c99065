package org.emini;

/**
 * Which flavour of the engine these tests run on. The double flavour's tests are generated from these
 * sources by the same rules as its engine (engine-double/README.md), which turn {@code Float} into
 * {@code Double}: so the comparison below is false here and true there. A test of something inherently
 * float (a pinned hash, float round-off itself) asks this to pin or skip per flavour.
 */
public final class Flavour {
    /** True in the double-precision flavour's run of these tests. */
    public static final boolean DOUBLE = Float.SIZE == Double.SIZE;

    private Flavour() {
    }
}
