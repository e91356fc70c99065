package org.emini.io;

/**
 * A spring record: a Hooke spring between anchor 1 on body 1 and anchor 2 on body 2 with a rest
 * length and a constant; a constant ≤ 0 makes it a rigid distance link.
 */
public final class PhySpring extends PhyPairConstraint {
    private int restLength;
    private int coefficient;

    /** Creates a rigid link of rest length 0 between body 0 and body 0. */
    public PhySpring() {
    }

    @Override
    public int getType() {
        return TYPE_SPRING;
    }

    /**
     * The rest length as stored (FX px; used as stored, never recomputed).
     *
     * @return the raw value
     */
    public int getRestLengthRaw() {
        return restLength;
    }

    /**
     * Sets the rest length as stored.
     *
     * @param raw the raw FX value
     */
    public void setRestLengthRaw(int raw) {
        restLength = raw;
    }

    /**
     * The rest length.
     *
     * @return raw / 4096 (px)
     */
    public float getRestLength() {
        return PhyFixed.fx(restLength);
    }

    /**
     * The spring constant as stored (FX force per px).
     *
     * @return the raw value
     */
    public int getCoefficientRaw() {
        return coefficient;
    }

    /**
     * Sets the spring constant as stored.
     *
     * @param raw the raw FX value
     */
    public void setCoefficientRaw(int raw) {
        coefficient = raw;
    }

    /**
     * The spring constant.
     *
     * @return raw / 4096 (mass/s² per px of stretch; ≤ 0 means rigid)
     */
    public float getCoefficient() {
        return PhyFixed.fx(coefficient);
    }

    /**
     * Whether the spring is a rigid distance link (constant ≤ 0).
     *
     * @return true when rigid
     */
    public boolean isRigid() {
        return coefficient <= 0;
    }

    static PhySpring readSpring(PhyInput in, int bodiesSoFar) throws PhyFormatException {
        PhySpring s = new PhySpring();
        s.readPair(in, bodiesSoFar);
        s.restLength = in.i32("rest length");
        s.coefficient = in.i32("coefficient");
        return s;
    }

    @Override
    void writeFields(PhyOutput out) {
        writePair(out);
        out.i32(restLength);
        out.i32(coefficient);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PhySpring)) {
            return false;
        }
        PhySpring s = (PhySpring) o;
        return pairEquals(s) && restLength == s.restLength && coefficient == s.coefficient;
    }

    @Override
    public int hashCode() {
        return pairHash() * 31 + restLength * 7 + coefficient;
    }

    @Override
    public String toString() {
        return "PhySpring[bodies " + getBody1() + ", " + getBody2() + ", rest " + getRestLength() + ", k "
                + getCoefficient() + "]";
    }
}
