package org.emini.io;

/**
 * The common part of joints and springs: two bodies and an anchor on each, given in that body's
 * local frame (unrotated, relative to its position).
 */
public abstract class PhyPairConstraint extends PhyConstraint {
    private int body1;
    private PhyVector anchor1 = PhyVector.ZERO;
    private int body2;
    private PhyVector anchor2 = PhyVector.ZERO;

    PhyPairConstraint() {
    }

    /**
     * The first body's index in the body list.
     *
     * @return 0 to 255
     */
    public int getBody1() {
        return body1;
    }

    /**
     * Sets the first body.
     *
     * @param index 0 to 255
     */
    public void setBody1(int index) {
        body1 = PhyWorld.checkU8("PhyPairConstraint.setBody1", "index", index);
    }

    /**
     * The anchor on the first body, in its local frame.
     *
     * @return the anchor (px)
     */
    public PhyVector getAnchor1() {
        return anchor1;
    }

    /**
     * Sets the anchor on the first body.
     *
     * @param anchor the anchor in body 1's local frame (px)
     */
    public void setAnchor1(PhyVector anchor) {
        anchor1 = PhyWorld.checkNotNull("PhyPairConstraint.setAnchor1", "anchor", anchor);
    }

    /**
     * The second body's index in the body list.
     *
     * @return 0 to 255
     */
    public int getBody2() {
        return body2;
    }

    /**
     * Sets the second body.
     *
     * @param index 0 to 255
     */
    public void setBody2(int index) {
        body2 = PhyWorld.checkU8("PhyPairConstraint.setBody2", "index", index);
    }

    /**
     * The anchor on the second body, in its local frame.
     *
     * @return the anchor (px)
     */
    public PhyVector getAnchor2() {
        return anchor2;
    }

    /**
     * Sets the anchor on the second body.
     *
     * @param anchor the anchor in body 2's local frame (px)
     */
    public void setAnchor2(PhyVector anchor) {
        anchor2 = PhyWorld.checkNotNull("PhyPairConstraint.setAnchor2", "anchor", anchor);
    }

    @Override
    public boolean concernsBody(int bodyIndex) {
        return body1 == bodyIndex || body2 == bodyIndex;
    }

    void readPair(PhyInput in, int bodiesSoFar) throws PhyFormatException {
        body1 = in.index("body 1 index", bodiesSoFar);
        anchor1 = in.vector("anchor 1");
        body2 = in.index("body 2 index", bodiesSoFar);
        anchor2 = in.vector("anchor 2");
    }

    void writePair(PhyOutput out) {
        out.index("body 1 index", body1, out.bodies);
        out.vector(anchor1);
        out.index("body 2 index", body2, out.bodies);
        out.vector(anchor2);
    }

    boolean pairEquals(PhyPairConstraint o) {
        return body1 == o.body1 && anchor1.equals(o.anchor1) && body2 == o.body2 && anchor2.equals(o.anchor2)
                && userDataEquals(o);
    }

    int pairHash() {
        return ((body1 * 31 + anchor1.hashCode()) * 31 + body2) * 31 + anchor2.hashCode() + userDataHash();
    }
}
