package org.emini.io;

/**
 * The world record: gravity and damping, and the world's user data. Timestep, iteration counts,
 * dynamic-iteration mode and simulation area are not stored; a loaded world uses the defaults.
 *
 * <p>Damping is kept as the two per-tick damping fractions of version 10 (FX). Older words store
 * one retention factor r for both, and the original loads the damping as 4096 − r (32-bit
 * arithmetic); this model does the same, and the writer stores 4096 − damping back, which gives
 * the same bytes.
 */
public final class PhyWorldSettings extends PhyElement {
    private PhyVector gravity = new PhyVector(0, 100 * PhyFixed.FX_ONE);
    private int dampingLinear;
    private int dampingRotational;

    /** Creates the original's defaults: gravity (0, 100) px/s², no damping. */
    public PhyWorldSettings() {
    }

    /**
     * Gravity, in any direction.
     *
     * @return gravity (px/s²; +y points down the screen)
     */
    public PhyVector getGravity() {
        return gravity;
    }

    /**
     * Sets gravity.
     *
     * @param gravity gravity (px/s²)
     */
    public void setGravity(PhyVector gravity) {
        this.gravity = PhyWorld.checkNotNull("PhyWorldSettings.setGravity", "gravity", gravity);
    }

    /**
     * The linear damping as loaded (FX fraction of linear velocity removed per tick).
     *
     * @return the raw value
     */
    public int getDampingLinearRaw() {
        return dampingLinear;
    }

    /**
     * Sets the linear damping.
     *
     * @param raw the raw FX value
     */
    public void setDampingLinearRaw(int raw) {
        dampingLinear = raw;
    }

    /**
     * The linear damping.
     *
     * @return raw / 4096 (fraction per tick)
     */
    public float getDampingLinear() {
        return PhyFixed.fx(dampingLinear);
    }

    /**
     * The rotational damping as loaded (FX fraction of angular velocity removed per tick).
     *
     * @return the raw value
     */
    public int getDampingRotationalRaw() {
        return dampingRotational;
    }

    /**
     * Sets the rotational damping.
     *
     * @param raw the raw FX value
     */
    public void setDampingRotationalRaw(int raw) {
        dampingRotational = raw;
    }

    /**
     * The rotational damping.
     *
     * @return raw / 4096 (fraction per tick)
     */
    public float getDampingRotational() {
        return PhyFixed.fx(dampingRotational);
    }

    static PhyWorldSettings read(PhyInput in) throws PhyFormatException {
        int v = in.version();
        PhyWorldSettings w = new PhyWorldSettings();
        w.gravity = in.vector("gravity");
        if (PhyVersion.hasSeparateDamping(v)) {
            w.dampingLinear = in.i32("linear damping");
            w.dampingRotational = in.i32("rotational damping");
        } else {
            int damping = PhyFixed.FX_ONE - in.i32("retention factor");
            w.dampingLinear = damping;
            w.dampingRotational = damping;
        }
        w.readUserData(in, PhyVersion.othersHaveUserData(v));
        return w;
    }

    void write(PhyOutput out) {
        int v = out.version();
        out.vector(gravity);
        if (PhyVersion.hasSeparateDamping(v)) {
            out.i32(dampingLinear);
            out.i32(dampingRotational);
        } else if (dampingLinear == dampingRotational) {
            out.i32(PhyFixed.FX_ONE - dampingLinear);
        } else {
            throw new IllegalArgumentException("PhyWriter.write: version " + PhyVersion.toString(v)
                    + " stores one damping for both; the world has linear " + getDampingLinear()
                    + " and rotational " + getDampingRotational());
        }
        out.userData(PhyVersion.othersHaveUserData(v), this);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PhyWorldSettings)) {
            return false;
        }
        PhyWorldSettings w = (PhyWorldSettings) o;
        return gravity.equals(w.gravity) && dampingLinear == w.dampingLinear
                && dampingRotational == w.dampingRotational && userDataEquals(w);
    }

    @Override
    public int hashCode() {
        return (gravity.hashCode() * 31 + dampingLinear) * 31 + dampingRotational + userDataHash();
    }

    @Override
    public String toString() {
        return "PhyWorldSettings[gravity " + gravity + ", damping " + getDampingLinear() + "/"
                + getDampingRotational() + "]";
    }
}
