package org.emini.io;

/**
 * A constraint record: a {@link PhyJoint}, {@link PhySpring} or {@link PhyMotor}, stored with a
 * leading type byte. Bodies are named by their index in the body list (file order).
 */
public abstract class PhyConstraint extends PhyElement {
    /** Type byte of a joint. */
    public static final int TYPE_JOINT = 0;
    /** Type byte of a spring. */
    public static final int TYPE_SPRING = 1;
    /** Type byte reserved for scripts; never stored. */
    public static final int TYPE_SCRIPT = 2;
    /** Type byte of a motor. */
    public static final int TYPE_MOTOR = 3;

    PhyConstraint() {
    }

    /**
     * The type byte.
     *
     * @return {@link #TYPE_JOINT}, {@link #TYPE_SPRING} or {@link #TYPE_MOTOR}
     */
    public abstract int getType();

    /**
     * Whether the constraint acts on a body.
     *
     * @param bodyIndex the body's index in the body list
     * @return true when it names that body
     */
    public abstract boolean concernsBody(int bodyIndex);

    abstract void writeFields(PhyOutput out);

    static PhyConstraint read(PhyInput in, int bodiesSoFar) throws PhyFormatException {
        int at = in.position();
        int type = in.u8("type");
        PhyConstraint c;
        switch (type) {
            case TYPE_JOINT:
                c = PhyJoint.readJoint(in, bodiesSoFar);
                break;
            case TYPE_SPRING:
                c = PhySpring.readSpring(in, bodiesSoFar);
                break;
            case TYPE_MOTOR:
                c = PhyMotor.readMotor(in, bodiesSoFar);
                break;
            default:
                // The original skips the record unread and loses its place in the stream.
                throw new PhyFormatException(at, in.describe("type", -1) + " 0 (joint), 1 (spring) or 3 (motor)",
                        Integer.toString(type));
        }
        c.readUserData(in, PhyVersion.othersHaveUserData(in.version()));
        return c;
    }

    void write(PhyOutput out) {
        out.u8(getType());
        writeFields(out);
        out.userData(PhyVersion.othersHaveUserData(out.version()), this);
    }
}
