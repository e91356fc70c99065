package org.emini.harness.fuzz.world;

/**
 * Moving the world far from the origin changes the relative motion by less than a bound: a separated
 * or smooth world (in turns) against the same world moved by (8192, −4096) px, compared relative to
 * where each started. The bound is {@link #TOLERANCE} px + {@link #RELATIVE} of the motion + half a
 * float step at that distance (2⁻¹¹ px) for every substep run.
 *
 * <p>Why: a float between 8192 and 16384 resolves 2⁻¹⁰ px; each position update of each substep
 * rounds to that, so a run drifts by up to half of it per substep when the roundings add up (a
 * constant velocity rounds the same way every time: measured up to 0.58 px in 2 s of smooth motion).
 * The generated world's own values stay exact there (multiples of 1/16 px). Contacts see the same
 * resolution in their depths; 0.25 px plus 1% of the motion leaves room for a landing body's friction
 * and flags a world whose physics depends on where it is.
 */
final class TranslationRelation extends TransformRelation {
    /** The shift (px): exact in floats for every generated value. */
    static final float DX = 8192f;
    /** The shift (px). */
    static final float DY = -4096f;
    /** Absolute tolerance (px). */
    static final double TOLERANCE = 0.25;
    /** Relative tolerance (fraction of the largest distance moved). */
    static final double RELATIVE = 0.01;

    @Override
    public ViolationKind kind() {
        return ViolationKind.TRANSLATION;
    }

    @Override
    void transform(Recipe copy) {
        Transforms.translate(copy, DX, DY);
    }

    @Override
    String label() {
        return "moved by (8192, -4096) px";
    }

    @Override
    int sign() {
        return 1;
    }

    @Override
    double dx() {
        return DX;
    }

    @Override
    double dy() {
        return DY;
    }

    @Override
    double bound(Recipe r, Deviation d, int ticks) {
        return TOLERANCE + RELATIVE * d.path() + ticks * r.iterations * 0x1p-11;
    }
}
