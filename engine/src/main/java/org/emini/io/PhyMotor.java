package org.emini.io;

/**
 * A motor record: drives one body's angular velocity (rotational motor) or its velocity along a
 * target vector (linear motor), with the accumulated impulse per tick capped by a maximum.
 */
public final class PhyMotor extends PhyConstraint {
    /** Flag bit 0: rotational motor. */
    public static final int FLAG_ROTATIONAL = 1;
    /** Flag bit 1: the target is relative to the body's rotation. */
    public static final int FLAG_RELATIVE = 2;
    /** Flag bit 2: a linear motor also brakes the velocity orthogonal to its target. */
    public static final int FLAG_FIX_ORTHOGONAL = 4;

    private int body;
    private int targetA;
    private int targetB;
    private int maxForce;
    private int flags;

    /** Creates a linear motor on body 0 with a zero target and cap. */
    public PhyMotor() {
    }

    @Override
    public int getType() {
        return TYPE_MOTOR;
    }

    /**
     * The body's index in the body list.
     *
     * @return 0 to 255
     */
    public int getBody() {
        return body;
    }

    /**
     * Sets the body.
     *
     * @param index 0 to 255
     */
    public void setBody(int index) {
        body = PhyWorld.checkU8("PhyMotor.setBody", "index", index);
    }

    @Override
    public boolean concernsBody(int bodyIndex) {
        return body == bodyIndex;
    }

    /**
     * Target A as stored: a rotational motor's target angular velocity (2FX rad/s, original sign:
     * positive turns counter-clockwise on screen), a linear motor's target x velocity (FX px/s).
     *
     * @return the raw value
     */
    public int getTargetARaw() {
        return targetA;
    }

    /**
     * Sets target A as stored.
     *
     * @param raw the raw value
     */
    public void setTargetARaw(int raw) {
        targetA = raw;
    }

    /**
     * Target B as stored: a linear motor's target y velocity (FX px/s); unused (0) for a
     * rotational motor.
     *
     * @return the raw value
     */
    public int getTargetBRaw() {
        return targetB;
    }

    /**
     * Sets target B as stored.
     *
     * @param raw the raw value
     */
    public void setTargetBRaw(int raw) {
        targetB = raw;
    }

    /**
     * A rotational motor's target angular velocity in the original's sign.
     *
     * @return target A / 2²⁴ (rad/s); the engine's ω is the negation
     */
    public float getTargetAngularVelocity() {
        return PhyFixed.fx2(targetA);
    }

    /**
     * A linear motor's target velocity.
     *
     * @return (target A, target B) as FX (px/s)
     */
    public PhyVector getTargetVelocity() {
        return new PhyVector(targetA, targetB);
    }

    /**
     * The cap on the accumulated impulse per tick as stored (FX).
     *
     * @return the raw value
     */
    public int getMaxForceRaw() {
        return maxForce;
    }

    /**
     * Sets the cap as stored.
     *
     * @param raw the raw FX value
     */
    public void setMaxForceRaw(int raw) {
        maxForce = raw;
    }

    /**
     * The cap on the accumulated impulse per tick.
     *
     * @return raw / 4096
     */
    public float getMaxForce() {
        return PhyFixed.fx(maxForce);
    }

    /**
     * The flag byte: {@link #FLAG_ROTATIONAL}, {@link #FLAG_RELATIVE},
     * {@link #FLAG_FIX_ORTHOGONAL} (the designer never writes the last).
     *
     * @return 0 to 255
     */
    public int getFlags() {
        return flags;
    }

    /**
     * Sets the flag byte.
     *
     * @param flags 0 to 255
     */
    public void setFlags(int flags) {
        this.flags = PhyWorld.checkU8("PhyMotor.setFlags", "flags", flags);
    }

    /**
     * Whether the motor is rotational.
     *
     * @return flag bit 0
     */
    public boolean isRotational() {
        return (flags & FLAG_ROTATIONAL) != 0;
    }

    static PhyMotor readMotor(PhyInput in, int bodiesSoFar) throws PhyFormatException {
        PhyMotor m = new PhyMotor();
        m.body = in.index("body index", bodiesSoFar);
        m.targetA = in.i32("target A");
        m.targetB = in.i32("target B");
        m.maxForce = in.i32("max force");
        m.flags = in.u8("flags");
        return m;
    }

    @Override
    void writeFields(PhyOutput out) {
        out.index("body index", body, out.bodies);
        out.i32(targetA);
        out.i32(targetB);
        out.i32(maxForce);
        out.u8(flags);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PhyMotor)) {
            return false;
        }
        PhyMotor m = (PhyMotor) o;
        return body == m.body && targetA == m.targetA && targetB == m.targetB && maxForce == m.maxForce
                && flags == m.flags && userDataEquals(m);
    }

    @Override
    public int hashCode() {
        return (((body * 31 + targetA) * 31 + targetB) * 31 + maxForce) * 31 + flags + userDataHash();
    }

    @Override
    public String toString() {
        return "PhyMotor[body " + body + ", flags " + flags + "]";
    }
}
