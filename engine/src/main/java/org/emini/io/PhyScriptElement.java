package org.emini.io;

/**
 * One element of a script: a type, two values and a duration in ticks. Immutable.
 *
 * <table>
 * <caption>Element types and their values</caption>
 * <tr><th>type</th><th>A, B</th></tr>
 * <tr><td>0 none</td><td>unused</td></tr>
 * <tr><td>1 position</td><td>x, y (FX px): sets the position</td></tr>
 * <tr><td>2 velocity</td><td>vx, vy (FX px/s): sets the velocity</td></tr>
 * <tr><td>3 acceleration</td><td>ax, ay (FX px/s²): added each tick × dt</td></tr>
 * <tr><td>4 angle</td><td>A (2FX rad): sets the angle; B unused</td></tr>
 * <tr><td>5 angular velocity</td><td>A (2FX rad/s, original sign): sets ω; B unused</td></tr>
 * <tr><td>6 angular acceleration</td><td>A (2FX rad/s², original sign): added each tick × dt</td></tr>
 * </table>
 */
public final class PhyScriptElement {
    /** Type 0: no action. */
    public static final int TYPE_NONE = 0;
    /** Type 1: set the position. */
    public static final int TYPE_POSITION = 1;
    /** Type 2: set the velocity. */
    public static final int TYPE_VELOCITY = 2;
    /** Type 3: accelerate. */
    public static final int TYPE_ACCELERATION = 3;
    /** Type 4: set the angle. */
    public static final int TYPE_ANGLE = 4;
    /** Type 5: set the angular velocity. */
    public static final int TYPE_ANGULAR_VELOCITY = 5;
    /** Type 6: accelerate the rotation. */
    public static final int TYPE_ANGULAR_ACCELERATION = 6;

    /** The bytes an element takes: type, A, B, ticks. */
    static final int BYTES = 10;

    private final int type;
    private final int a;
    private final int b;
    private final int ticks;

    /**
     * Creates an element.
     *
     * @param type the type byte, 0 to 255 (0 to 6 are defined)
     * @param aRaw value A as stored
     * @param bRaw value B as stored
     * @param ticks the duration byte, 0 to 255 (0 never ends)
     */
    public PhyScriptElement(int type, int aRaw, int bRaw, int ticks) {
        this.type = PhyWorld.checkU8("PhyScriptElement", "type", type);
        this.a = aRaw;
        this.b = bRaw;
        this.ticks = PhyWorld.checkU8("PhyScriptElement", "ticks", ticks);
    }

    /**
     * The type byte.
     *
     * @return 0 to 255
     */
    public int getType() {
        return type;
    }

    /**
     * Value A as stored (FX or 2FX by type).
     *
     * @return the raw value
     */
    public int getARaw() {
        return a;
    }

    /**
     * Value B as stored (FX for types 1 to 3).
     *
     * @return the raw value
     */
    public int getBRaw() {
        return b;
    }

    /**
     * The duration byte.
     *
     * @return 0 to 255
     */
    public int getTicks() {
        return ticks;
    }

    static PhyScriptElement read(PhyInput in, int item) throws PhyFormatException {
        int t = in.u8("element # type", item);
        int ra = in.i32("element # value A", item);
        int rb = in.i32("element # value B", item);
        return new PhyScriptElement(t, ra, rb, in.u8("element # ticks", item));
    }

    void write(PhyOutput out) {
        out.u8(type);
        out.i32(a);
        out.i32(b);
        out.u8(ticks);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PhyScriptElement)) {
            return false;
        }
        PhyScriptElement e = (PhyScriptElement) o;
        return type == e.type && a == e.a && b == e.b && ticks == e.ticks;
    }

    @Override
    public int hashCode() {
        return ((type * 31 + a) * 31 + b) * 31 + ticks;
    }

    @Override
    public String toString() {
        return "PhyScriptElement[type " + type + ", " + a + ", " + b + ", " + ticks + " ticks]";
    }
}
