package org.emini.event;

import java.util.Arrays;

/**
 * A scripted motion, the original's {@code Script}: a list of elements, each of which sets or
 * changes a body's position, velocity, angle or angular velocity every tick for a number of ticks.
 * A world runs a script on a body ({@code World.applyScript(script, body)}, the original's
 * {@code script.applyToBody(body, world)}), or an event starts it on the body it reports
 * ({@link Event#setScript}); world files store scripts and the bodies they run on.
 *
 * <p>Timing, as in the original: each tick of a run applies the current element at the start of the
 * tick, before external forces and gravity. The first element lasts {@code ticks} ticks, every later
 * one (and the first again after a restart) {@code ticks} + 1; an element of 0 ticks never ends.
 * After the last element comes one tick without action; on the tick after it the script starts
 * again at its first element if it restarts, or the run ends.
 *
 * <p>Units are the engine's (px, s, rad; positive angular velocity grows the angle): a world file's
 * angular velocities and accelerations are negated on loading, as everywhere.
 */
public final class Script {
    /** An element that does nothing. */
    public static final int NONE = 0;
    /** Sets the position to (a, b) px. */
    public static final int POSITION = 1;
    /** Sets the velocity to (a, b) px/s. */
    public static final int VELOCITY = 2;
    /** Adds (a, b)·dt to the velocity: an acceleration in px/s². */
    public static final int ACCELERATION = 3;
    /** Sets the angle to a rad. */
    public static final int ANGLE = 4;
    /** Sets the angular velocity to a rad/s. */
    public static final int ANGULAR_VELOCITY = 5;
    /** Adds a·dt to the angular velocity: an angular acceleration in rad/s². */
    public static final int ANGULAR_ACCELERATION = 6;
    /** The most ticks an element lasts, as the file's byte holds (0 means for ever). */
    public static final int MAX_TICKS = 255;

    private final boolean restart;
    private int[] types = new int[4];
    private float[] a = new float[4];
    private float[] b = new float[4];
    private int[] ticks = new int[4];
    private int count;

    /**
     * Creates an empty script.
     *
     * @param restart true to start again at the first element after the last
     */
    public Script(boolean restart) {
        this.restart = restart;
    }

    /**
     * Adds an element.
     *
     * @param type {@link #NONE} to {@link #ANGULAR_ACCELERATION}
     * @param a the first value (x, or the angular value)
     * @param b the second value (y; ignored by the angular types)
     * @param ticks how many ticks it lasts, 0 (for ever) to {@link #MAX_TICKS}
     * @return this script
     */
    public Script addElement(int type, float a, float b, int ticks) {
        if (type < NONE || type > ANGULAR_ACCELERATION) {
            throw new IllegalArgumentException("Script.addElement: type must be 0 to 6, was " + type);
        }
        if (!(Math.abs(a) <= Float.MAX_VALUE) || !(Math.abs(b) <= Float.MAX_VALUE)) {
            throw new IllegalArgumentException("Script.addElement: a and b must be finite, were " + a + " and " + b);
        }
        if (ticks < 0 || ticks > MAX_TICKS) {
            throw new IllegalArgumentException("Script.addElement: ticks must be 0 to " + MAX_TICKS + ", was " + ticks);
        }
        if (count == types.length) {
            types = Arrays.copyOf(types, 2 * count);
            this.a = Arrays.copyOf(this.a, 2 * count);
            this.b = Arrays.copyOf(this.b, 2 * count);
            this.ticks = Arrays.copyOf(this.ticks, 2 * count);
        }
        types[count] = type;
        this.a[count] = a;
        this.b[count] = b;
        this.ticks[count] = ticks;
        count++;
        return this;
    }

    /**
     * Adds an element with one value (the angular types).
     *
     * @param type {@link #NONE} to {@link #ANGULAR_ACCELERATION}
     * @param a the value
     * @param ticks how many ticks it lasts, 0 (for ever) to {@link #MAX_TICKS}
     * @return this script
     */
    public Script addElement(int type, float a, int ticks) {
        return addElement(type, a, 0f, ticks);
    }

    /**
     * Whether the script starts again after its last element.
     *
     * @return true when it restarts
     */
    public boolean isRestarting() {
        return restart;
    }

    /**
     * The number of elements.
     *
     * @return the count
     */
    public int getElementCount() {
        return count;
    }

    /**
     * An element's type.
     *
     * @param i 0 to {@link #getElementCount()} − 1
     * @return the type
     */
    public int getType(int i) {
        return types[check(i)];
    }

    /**
     * An element's first value.
     *
     * @param i 0 to {@link #getElementCount()} − 1
     * @return a
     */
    public float getA(int i) {
        return a[check(i)];
    }

    /**
     * An element's second value.
     *
     * @param i 0 to {@link #getElementCount()} − 1
     * @return b
     */
    public float getB(int i) {
        return b[check(i)];
    }

    /**
     * How many ticks an element lasts (0: for ever).
     *
     * @param i 0 to {@link #getElementCount()} − 1
     * @return the ticks
     */
    public int getTicks(int i) {
        return ticks[check(i)];
    }

    private int check(int i) {
        if (i < 0 || i >= count) {
            throw new IndexOutOfBoundsException("Script: element " + i + " of " + count);
        }
        return i;
    }

    @Override
    public String toString() {
        return "Script(" + count + " elements" + (restart ? ", restarting)" : ")");
    }
}
