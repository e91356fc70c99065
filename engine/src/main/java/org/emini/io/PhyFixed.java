package org.emini.io;

/**
 * The original engine's fixed-point numbers and their conversion to the engine's float units.
 *
 * <ul>
 * <li><b>FX</b>: signed 32-bit, 12 fractional bits; value = raw / 4096. Lengths (px), velocities
 * (px/s), accelerations (px/s²), material factors (elasticity, friction: 1.0 = 4096), mass,
 * damping fractions, spring constants, forces, times (s) and rates (1/s).</li>
 * <li><b>2FX</b>: signed 32-bit, 24 fractional bits; value = raw / 16777216. Angles (rad) and
 * angular velocities and accelerations (rad/s, rad/s²). π is stored as {@link #PI_2FX}.</li>
 * <li><b>Percent</b>: the original's integer material setters take percent and store
 * {@code percent * 4096 / 100} (integer division), so 99 % is the raw FX value 4055.</li>
 * </ul>
 * The conversions to float are exact up to the float's 24-bit mantissa: the raw integer is rounded
 * to the nearest float once and then scaled by a power of two.
 */
public final class PhyFixed {
    /** Fractional bits of an FX value. */
    public static final int FX_BITS = 12;
    /** 1.0 as a raw FX value. */
    public static final int FX_ONE = 1 << FX_BITS;
    /** Fractional bits of a 2FX value. */
    public static final int FX2_BITS = 24;
    /** 1.0 as a raw 2FX value. */
    public static final int FX2_ONE = 1 << FX2_BITS;
    /** π as the original stores it (2FX): 52707178 (π·2²⁴ = 52707178.8, truncated). */
    public static final int PI_2FX = 52707178;
    /** 2π as the original uses it when wrapping angles: 2 × {@link #PI_2FX}. */
    public static final int TWO_PI_2FX = 2 * PI_2FX;

    private static final float FX_SCALE = 1f / FX_ONE;
    private static final float FX2_SCALE = 1f / FX2_ONE;

    private PhyFixed() {
    }

    /**
     * Converts a raw FX value to a float.
     *
     * @param raw the raw value
     * @return raw / 4096
     */
    public static float fx(int raw) {
        return raw * FX_SCALE;
    }

    /**
     * Converts a raw 2FX value to a float.
     *
     * @param raw the raw value
     * @return raw / 16777216
     */
    public static float fx2(int raw) {
        return raw * FX2_SCALE;
    }

    /**
     * Converts a float to the nearest raw FX value.
     *
     * @param value the value; |value| must be below 524288 (2³¹ / 4096)
     * @return round(value · 4096)
     * @throws IllegalArgumentException if the value is NaN or out of the FX range
     */
    public static int toFx(float value) {
        return toRaw("PhyFixed.toFx", value, FX_ONE);
    }

    /**
     * Converts a float to the nearest raw 2FX value.
     *
     * @param value the value; |value| must be below 128 (2³¹ / 2²⁴)
     * @return round(value · 16777216)
     * @throws IllegalArgumentException if the value is NaN or out of the 2FX range
     */
    public static int toFx2(float value) {
        return toRaw("PhyFixed.toFx2", value, FX2_ONE);
    }

    private static int toRaw(String where, float value, int one) {
        double scaled = Math.rint((double) value * one);
        if (!(scaled >= Integer.MIN_VALUE && scaled <= Integer.MAX_VALUE)) {
            throw new IllegalArgumentException(where + ": value " + value + " is outside the fixed-point range");
        }
        return (int) scaled;
    }

    /**
     * Wraps a raw 2FX angle into [0, {@link #TWO_PI_2FX}] as the original does when it sets a
     * body's angle (repeatedly adding or subtracting its 2π).
     *
     * @param angle2fx the raw angle
     * @return the wrapped raw angle
     */
    public static int wrapAngle2fx(int angle2fx) {
        int a = angle2fx;
        // At most 21 passes: |a| < 2^31 and 2π is about 2^26.65.
        while (a < 0) {
            a += TWO_PI_2FX;
        }
        while (a > TWO_PI_2FX) {
            a -= TWO_PI_2FX;
        }
        return a;
    }

    /**
     * The radius of a one-vertex (circle) shape as the fixed-point original computes it: the
     * length of the vertex vector by its approximate square root with one Newton step
     * ({@code FXVector.lengthFX}), truncated to whole pixels. It is 0 when the vertex lies within
     * one pixel of the origin (the original keeps a bounding radius of 0 then).
     *
     * @param xRaw the vertex x (raw FX)
     * @param yRaw the vertex y (raw FX)
     * @return the radius in whole pixels
     */
    public static int circleRadius(int xRaw, int yRaw) {
        long squared = (long) xRaw * xRaw + (long) yRaw * yRaw;
        // The original only takes the length when the squared length in whole px² is above 0.
        if ((int) (squared >> (2 * FX_BITS)) <= 0) {
            return 0;
        }
        int ix = xRaw < 0 ? -xRaw : xRaw;
        int iy = yRaw < 0 ? -yRaw : yRaw;
        if (ix < iy) {
            int t = ix;
            ix = iy;
            iy = t;
        }
        int t = iy + (iy >> 1);
        int guess = ix - (ix >> 5) - (ix >> 7) + (t >> 2) + (t >> 6);
        if (guess == 0) {
            return 0;
        }
        int length = (int) (squared / guess + guess) >> 1;
        return length >> FX_BITS;
    }
}
