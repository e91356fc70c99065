package org.emini.io;

/**
 * A body record: position, velocity, angle and angular velocity, the shape it uses, its flags and
 * collision layers. Also the layout of a sensor event's sensor body.
 */
public final class PhyBody extends PhyElement {
    /** Flag bit 0: the body is dynamic. */
    public static final int FLAG_DYNAMIC = 1;
    /** Flag bit 1: the body may rotate. */
    public static final int FLAG_ROTATES = 2;
    /** Flag bit 2: the body does <b>not</b> interact with other bodies. */
    public static final int FLAG_NOT_INTERACTING = 4;
    /** Flag bit 3: the body is <b>not</b> affected by gravity. */
    public static final int FLAG_NO_GRAVITY = 8;

    private int legacyMass;
    private PhyVector position = PhyVector.ZERO;
    private PhyVector velocity = PhyVector.ZERO;
    private int angle;
    private int angularVelocity;
    private int shapeIndex;
    private int flags = FLAG_DYNAMIC | FLAG_ROTATES;
    private int layers;

    /** Creates a dynamic, rotating body at the origin using shape 0. */
    public PhyBody() {
    }

    /**
     * The legacy mass that records of version words below 0x0500 start with (FX; the version-1
     * files hold 1.0 for dynamic bodies and 16777217 for static ones). Ignored by the original and
     * written only in those versions.
     *
     * @return the raw value
     */
    public int getLegacyMassRaw() {
        return legacyMass;
    }

    /**
     * Sets the legacy mass.
     *
     * @param raw the raw FX value
     */
    public void setLegacyMassRaw(int raw) {
        legacyMass = raw;
    }

    /**
     * The position of the body's reference point (its shape's origin and centre of rotation).
     *
     * @return the position (px)
     */
    public PhyVector getPosition() {
        return position;
    }

    /**
     * Sets the position.
     *
     * @param position the position (px)
     */
    public void setPosition(PhyVector position) {
        this.position = PhyWorld.checkNotNull("PhyBody.setPosition", "position", position);
    }

    /**
     * The linear velocity.
     *
     * @return the velocity (px/s)
     */
    public PhyVector getVelocity() {
        return velocity;
    }

    /**
     * Sets the linear velocity.
     *
     * @param velocity the velocity (px/s)
     */
    public void setVelocity(PhyVector velocity) {
        this.velocity = PhyWorld.checkNotNull("PhyBody.setVelocity", "velocity", velocity);
    }

    /**
     * The angle as stored (2FX rad; a growing angle turns the body clockwise on a y-down screen).
     *
     * @return the raw value
     */
    public int getAngleRaw() {
        return angle;
    }

    /**
     * Sets the angle as stored.
     *
     * @param raw the raw 2FX value
     */
    public void setAngleRaw(int raw) {
        angle = raw;
    }

    /**
     * The angle as the original loads it: wrapped into [0, 2π] ({@link PhyFixed#wrapAngle2fx}).
     *
     * @return the angle (rad)
     */
    public float getAngle() {
        return PhyFixed.fx2(PhyFixed.wrapAngle2fx(angle));
    }

    /**
     * The angular velocity as stored (2FX rad/s) with the original's sign: the original advances
     * angle ← angle − ω·dt, so a positive value turns the body counter-clockwise on screen.
     *
     * @return the raw value
     */
    public int getAngularVelocityRaw() {
        return angularVelocity;
    }

    /**
     * Sets the angular velocity as stored.
     *
     * @param raw the raw 2FX value, original sign
     */
    public void setAngularVelocityRaw(int raw) {
        angularVelocity = raw;
    }

    /**
     * The angular velocity in the original's sign convention.
     *
     * @return raw / 2²⁴ (rad/s); the engine's ω (which grows the angle) is the negation
     */
    public float getAngularVelocity() {
        return PhyFixed.fx2(angularVelocity);
    }

    /**
     * The index of the body's shape in the shape list.
     *
     * @return 0 to 255
     */
    public int getShapeIndex() {
        return shapeIndex;
    }

    /**
     * Sets the shape index.
     *
     * @param index 0 to 255
     */
    public void setShapeIndex(int index) {
        shapeIndex = PhyWorld.checkU8("PhyBody.setShapeIndex", "index", index);
    }

    /**
     * The flag byte: {@link #FLAG_DYNAMIC}, {@link #FLAG_ROTATES}, {@link #FLAG_NOT_INTERACTING},
     * {@link #FLAG_NO_GRAVITY}; bits 4 to 7 are unused and kept.
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
        this.flags = PhyWorld.checkU8("PhyBody.setFlags", "flags", flags);
    }

    /**
     * Whether the body is dynamic (flag bit 0).
     *
     * @return true when dynamic
     */
    public boolean isDynamic() {
        return (flags & FLAG_DYNAMIC) != 0;
    }

    /**
     * Whether the body may rotate (flag bit 1).
     *
     * @return true when it may rotate
     */
    public boolean canRotate() {
        return (flags & FLAG_ROTATES) != 0;
    }

    /**
     * Whether the body interacts with other bodies (flag bit 2 clear).
     *
     * @return true when interacting
     */
    public boolean isInteracting() {
        return (flags & FLAG_NOT_INTERACTING) == 0;
    }

    /**
     * Whether gravity acts on the body (flag bit 3 clear).
     *
     * @return true when affected by gravity
     */
    public boolean isAffectedByGravity() {
        return (flags & FLAG_NO_GRAVITY) == 0;
    }

    /**
     * The collision layers: bit k set for layer k (layer 31 makes the value negative). Two bodies
     * sharing a layer do not collide.
     *
     * @return the 32 layer bits
     */
    public int getCollisionLayers() {
        return layers;
    }

    /**
     * Sets the collision layers.
     *
     * @param layers the 32 layer bits
     */
    public void setCollisionLayers(int layers) {
        this.layers = layers;
    }

    static PhyBody read(PhyInput in, int shapesSoFar) throws PhyFormatException {
        int v = in.version();
        PhyBody b = new PhyBody();
        if (PhyVersion.bodyHasLegacyMass(v)) {
            b.legacyMass = in.i32("legacy mass");
        }
        b.position = in.vector("position");
        b.velocity = in.vector("velocity");
        b.angle = in.i32("angle");
        b.angularVelocity = in.i32("angular velocity");
        b.shapeIndex = in.index("shape index", shapesSoFar);
        b.flags = in.u8("flags");
        b.layers = in.i32("collision layers");
        b.readUserData(in, PhyVersion.shapeAndBodyHaveUserData(v));
        return b;
    }

    void write(PhyOutput out) {
        int v = out.version();
        if (PhyVersion.bodyHasLegacyMass(v)) {
            out.i32(legacyMass);
        }
        out.vector(position);
        out.vector(velocity);
        out.i32(angle);
        out.i32(angularVelocity);
        out.index("shape index", shapeIndex, out.shapes);
        out.u8(flags);
        out.i32(layers);
        out.userData(PhyVersion.shapeAndBodyHaveUserData(v), this);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PhyBody)) {
            return false;
        }
        PhyBody b = (PhyBody) o;
        return legacyMass == b.legacyMass && position.equals(b.position) && velocity.equals(b.velocity)
                && angle == b.angle && angularVelocity == b.angularVelocity && shapeIndex == b.shapeIndex
                && flags == b.flags && layers == b.layers && userDataEquals(b);
    }

    @Override
    public int hashCode() {
        return ((position.hashCode() * 31 + velocity.hashCode()) * 31 + angle) * 31 + shapeIndex * 7 + flags
                + layers + userDataHash();
    }

    @Override
    public String toString() {
        return "PhyBody[shape " + shapeIndex + " at " + position + ", flags " + flags + "]";
    }
}
