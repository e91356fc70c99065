package org.emini.io;

/**
 * An event record: a condition on bodies or constraints, optionally filtered to one body, shape
 * or constraint, checked by the world after each tick. Its id is its position in the event list.
 *
 * <table>
 * <caption>Event types and their targets A to D (internal units)</caption>
 * <tr><th>type</th><th>targets</th></tr>
 * <tr><td>0 body position</td><td>min x, min y, max x, max y (FX px, inclusive)</td></tr>
 * <tr><td>1 body velocity</td><td>min, max of the squared speed (FX px²/s²)</td></tr>
 * <tr><td>2 body rotation</td><td>min, max angle (2FX rad, body angle wrapped to [0, 2π])</td></tr>
 * <tr><td>3 body angular velocity</td><td>min, max (2FX rad/s, original sign)</td></tr>
 * <tr><td>4 body collision</td><td>&gt; 0 enables contacts above, right of, below, left of the
 * body position</td></tr>
 * <tr><td>5 body sensor</td><td>unused; the sensor body record follows</td></tr>
 * <tr><td>6 relative collision</td><td>A direction relative to the body angle (2FX rad), B minimum
 * cosine (FX)</td></tr>
 * <tr><td>10 constraint force</td><td>min, max of the constraint's impulse measure (FX)</td></tr>
 * </table>
 */
public final class PhyEvent extends PhyElement {
    /** Type 0: body position inside a rectangle. */
    public static final int TYPE_BODY_POSITION = 0;
    /** Type 1: body squared speed within a range. */
    public static final int TYPE_BODY_VELOCITY = 1;
    /** Type 2: body angle within a range. */
    public static final int TYPE_BODY_ROTATION = 2;
    /** Type 3: body angular velocity within a range. */
    public static final int TYPE_BODY_ANGULAR_VELOCITY = 3;
    /** Type 4: body collision in given directions. */
    public static final int TYPE_BODY_COLLISION = 4;
    /** Type 5: body overlaps a sensor body. */
    public static final int TYPE_BODY_SENSOR = 5;
    /** Type 6: body collision in a direction relative to its angle. */
    public static final int TYPE_BODY_COLLISION_RELATIVE = 6;
    /** Type 10: constraint impulse within a range. */
    public static final int TYPE_CONSTRAINT_FORCE = 10;

    private int type;
    private int legacyId;
    private int triggerOnce;
    private int bodyFilter = PhyWorld.NONE;
    private int shapeFilter = PhyWorld.NONE;
    private int constraintFilter = PhyWorld.NONE;
    private int targetA;
    private int targetB;
    private int targetC;
    private int targetD;
    private PhyBody sensor;

    /** Creates a position event without filters, targets 0. */
    public PhyEvent() {
    }

    /**
     * The type byte.
     *
     * @return 0 to 255 (0 to 6 and 10 are defined)
     */
    public int getType() {
        return type;
    }

    /**
     * Sets the type byte. A sensor event ({@link #TYPE_BODY_SENSOR}) needs a sensor body.
     *
     * @param type 0 to 255
     */
    public void setType(int type) {
        this.type = PhyWorld.checkU8("PhyEvent.setType", "type", type);
    }

    /**
     * The legacy id byte of the old event layout (version index below 4); ignored by the original
     * and written only in that layout.
     *
     * @return 0 to 255
     */
    public int getLegacyId() {
        return legacyId;
    }

    /**
     * Sets the legacy id byte.
     *
     * @param legacyId 0 to 255
     */
    public void setLegacyId(int legacyId) {
        this.legacyId = PhyWorld.checkU8("PhyEvent.setLegacyId", "legacyId", legacyId);
    }

    /**
     * The trigger-once byte (version index 4 and above); a value above 0 reports each parameter
     * only the first time its condition holds.
     *
     * @return 0 to 255
     */
    public int getTriggerOnceByte() {
        return triggerOnce;
    }

    /**
     * Sets the trigger-once byte.
     *
     * @param value 0 to 255
     */
    public void setTriggerOnceByte(int value) {
        triggerOnce = PhyWorld.checkU8("PhyEvent.setTriggerOnceByte", "value", value);
    }

    /**
     * Whether the event triggers once per parameter.
     *
     * @return true when the trigger-once byte is above 0
     */
    public boolean isTriggerOnce() {
        return triggerOnce > 0;
    }

    /**
     * The body filter: a body index in file order, or {@link PhyWorld#NONE} for any body.
     *
     * @return 0 to 255
     */
    public int getBodyFilter() {
        return bodyFilter;
    }

    /**
     * Sets the body filter.
     *
     * @param index a body index, or {@link PhyWorld#NONE}
     */
    public void setBodyFilter(int index) {
        bodyFilter = PhyWorld.checkU8("PhyEvent.setBodyFilter", "index", index);
    }

    /**
     * The shape filter: a shape-list index, or {@link PhyWorld#NONE} for any shape.
     *
     * @return 0 to 255
     */
    public int getShapeFilter() {
        return shapeFilter;
    }

    /**
     * Sets the shape filter.
     *
     * @param index a shape-list index, or {@link PhyWorld#NONE}
     */
    public void setShapeFilter(int index) {
        shapeFilter = PhyWorld.checkU8("PhyEvent.setShapeFilter", "index", index);
    }

    /**
     * The constraint filter (version index 4 and above): an index into the constraints stored
     * before the event, or {@link PhyWorld#NONE} for any.
     *
     * @return 0 to 255
     */
    public int getConstraintFilter() {
        return constraintFilter;
    }

    /**
     * Sets the constraint filter.
     *
     * @param index a constraint index, or {@link PhyWorld#NONE}
     */
    public void setConstraintFilter(int index) {
        constraintFilter = PhyWorld.checkU8("PhyEvent.setConstraintFilter", "index", index);
    }

    /**
     * A target as stored (see the class comment for units by type).
     *
     * @param i 0 to 3 for A to D
     * @return the raw value
     */
    public int getTargetRaw(int i) {
        switch (i) {
            case 0:
                return targetA;
            case 1:
                return targetB;
            case 2:
                return targetC;
            case 3:
                return targetD;
            default:
                throw new IndexOutOfBoundsException("PhyEvent.getTargetRaw: target " + i + " of 4");
        }
    }

    /**
     * Sets a target as stored.
     *
     * @param i 0 to 3 for A to D
     * @param raw the raw value
     */
    public void setTargetRaw(int i, int raw) {
        switch (i) {
            case 0:
                targetA = raw;
                break;
            case 1:
                targetB = raw;
                break;
            case 2:
                targetC = raw;
                break;
            case 3:
                targetD = raw;
                break;
            default:
                throw new IndexOutOfBoundsException("PhyEvent.setTargetRaw: target " + i + " of 4");
        }
    }

    /**
     * The sensor body of a sensor event (not part of the world's bodies).
     *
     * @return the sensor body, or null
     */
    public PhyBody getSensor() {
        return sensor;
    }

    /**
     * Sets the sensor body; stored only with {@link #TYPE_BODY_SENSOR}.
     *
     * @param sensor the sensor body, or null
     */
    public void setSensor(PhyBody sensor) {
        this.sensor = sensor;
    }

    static PhyEvent read(PhyInput in, PhyWorld soFar) throws PhyFormatException {
        int v = in.version();
        PhyEvent e = new PhyEvent();
        e.type = in.u8("type");
        boolean old = PhyVersion.eventHasLegacyId(v);
        if (old) {
            e.legacyId = in.u8("legacy id");
        } else {
            e.triggerOnce = in.u8("trigger-once flag");
        }
        e.bodyFilter = in.optionalIndex("body filter", soFar.getBodies().size());
        e.shapeFilter = in.optionalIndex("shape filter", soFar.getShapes().size());
        if (!old) {
            e.constraintFilter = in.optionalIndex("constraint filter", soFar.getConstraints().size());
        }
        e.targetA = in.i32("target A");
        e.targetB = in.i32("target B");
        e.targetC = in.i32("target C");
        e.targetD = in.i32("target D");
        if (e.type == TYPE_BODY_SENSOR) {
            int index = in.recordIndex();
            in.record("event " + index + " sensor body", -1);
            e.sensor = PhyBody.read(in, soFar.getShapes().size());
            in.record("event", index);
        }
        e.readUserData(in, PhyVersion.othersHaveUserData(v));
        return e;
    }

    void write(PhyOutput out) {
        int v = out.version();
        out.u8(type);
        boolean old = PhyVersion.eventHasLegacyId(v);
        if (old) {
            if (triggerOnce != 0 || constraintFilter != PhyWorld.NONE) {
                throw new IllegalArgumentException("PhyWriter.write: version " + PhyVersion.toString(v)
                        + " stores no trigger-once flag or constraint filter; " + out.describe() + " has them");
            }
            out.u8(legacyId);
        } else {
            out.u8(triggerOnce);
        }
        out.optionalIndex("body filter", bodyFilter, out.bodies);
        out.optionalIndex("shape filter", shapeFilter, out.shapes);
        if (!old) {
            out.optionalIndex("constraint filter", constraintFilter, out.constraints);
        }
        out.i32(targetA);
        out.i32(targetB);
        out.i32(targetC);
        out.i32(targetD);
        if ((type == TYPE_BODY_SENSOR) != (sensor != null)) {
            throw new IllegalArgumentException("PhyWriter.write: " + out.describe() + " of type " + type
                    + (sensor == null ? " needs a sensor body" : " cannot store its sensor body"));
        }
        if (sensor != null) {
            int index = out.recordIndex();
            out.record("event " + index + " sensor body", -1);
            sensor.write(out);
            out.record("event", index);
        }
        out.userData(PhyVersion.othersHaveUserData(v), this);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PhyEvent)) {
            return false;
        }
        PhyEvent e = (PhyEvent) o;
        return type == e.type && legacyId == e.legacyId && triggerOnce == e.triggerOnce
                && bodyFilter == e.bodyFilter && shapeFilter == e.shapeFilter
                && constraintFilter == e.constraintFilter && targetA == e.targetA && targetB == e.targetB
                && targetC == e.targetC && targetD == e.targetD
                && (sensor == null ? e.sensor == null : sensor.equals(e.sensor)) && userDataEquals(e);
    }

    @Override
    public int hashCode() {
        return (((type * 31 + bodyFilter) * 31 + shapeFilter) * 31 + targetA) * 31 + targetB + targetC * 7 + targetD
                + userDataHash();
    }

    @Override
    public String toString() {
        return "PhyEvent[type " + type + ", targets " + targetA + ", " + targetB + ", " + targetC + ", " + targetD
                + "]";
    }
}
