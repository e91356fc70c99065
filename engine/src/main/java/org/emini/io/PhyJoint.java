package org.emini.io;

/**
 * A joint record: pins anchor 1 on body 1 to anchor 2 on body 2; a fixed joint also locks the
 * bodies' relative angle at the value it has when the world is loaded.
 */
public final class PhyJoint extends PhyPairConstraint {
    private int fixed;

    /** Creates a free joint between body 0 and body 0 with both anchors at the origin. */
    public PhyJoint() {
    }

    @Override
    public int getType() {
        return TYPE_JOINT;
    }

    /**
     * The fixed byte as stored; a value above 0 makes the joint fixed.
     *
     * @return 0 to 255
     */
    public int getFixedByte() {
        return fixed;
    }

    /**
     * Sets the fixed byte.
     *
     * @param value 0 to 255
     */
    public void setFixedByte(int value) {
        fixed = PhyWorld.checkU8("PhyJoint.setFixedByte", "value", value);
    }

    /**
     * Whether the joint is fixed (also locks the relative angle).
     *
     * @return true when the fixed byte is above 0
     */
    public boolean isFixed() {
        return fixed > 0;
    }

    static PhyJoint readJoint(PhyInput in, int bodiesSoFar) throws PhyFormatException {
        PhyJoint j = new PhyJoint();
        j.readPair(in, bodiesSoFar);
        j.fixed = in.u8("fixed flag");
        return j;
    }

    @Override
    void writeFields(PhyOutput out) {
        writePair(out);
        out.u8(fixed);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof PhyJoint && pairEquals((PhyJoint) o) && fixed == ((PhyJoint) o).fixed;
    }

    @Override
    public int hashCode() {
        return pairHash() + fixed;
    }

    @Override
    public String toString() {
        return "PhyJoint[bodies " + getBody1() + ", " + getBody2() + (isFixed() ? ", fixed]" : "]");
    }
}
