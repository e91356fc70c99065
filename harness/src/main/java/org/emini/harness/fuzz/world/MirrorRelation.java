package org.emini.harness.fuzz.world;

/**
 * Mirroring the world in x → −x (Transforms.mirror: shapes, positions, velocities, gravity, anchors,
 * angles, angular velocities and rotational motor targets, segment faces) mirrors the motion: every
 * body of the mirrored world must stay within a bound of the mirror image of its original. Checked on
 * smooth worlds (no contacts) and separated worlds (bodies landing, sliding and rolling on floors, no
 * body meeting another) in turns.
 *
 * <p>Why not exact: a mirrored polygon lists its vertices in another order, so sums (mass
 * properties, contact points, the order of a contact's two points) round differently, about one float
 * ulp (10⁻⁷ relative) per operation. Without contacts that stays at round-off: bound
 * {@link #SMOOTH} px + 10⁻⁴ of the motion (measured: under 2·10⁻⁴ px in 400 worlds). With contacts, a
 * landing or sliding body feels those bits through friction for a while: 0.5 px plus 1% of the motion
 * (a mirror-symmetric engine; one that pushes bodies sideways in a fixed direction fails it).
 */
final class MirrorRelation extends TransformRelation {
    /** Absolute tolerance with contacts (px). */
    static final double TOLERANCE = 0.5;
    /** Absolute tolerance without contacts (px). */
    static final double SMOOTH = 0.01;
    /** Relative tolerance with contacts (fraction of the largest distance moved). */
    static final double RELATIVE = 0.01;

    @Override
    public ViolationKind kind() {
        return ViolationKind.MIRROR;
    }

    @Override
    void transform(Recipe copy) {
        Transforms.mirror(copy);
    }

    @Override
    String label() {
        return "mirrored";
    }

    @Override
    int sign() {
        return -1;
    }

    @Override
    double dx() {
        return 0;
    }

    @Override
    double dy() {
        return 0;
    }

    @Override
    double bound(Recipe r, Deviation d, int ticks) {
        return r.profile == Profile.SMOOTH ? SMOOTH + 1e-4 * d.path() : TOLERANCE + RELATIVE * d.path();
    }
}
