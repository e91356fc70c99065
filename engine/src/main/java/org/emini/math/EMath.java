package org.emini.math;

/**
 * The one place where the engine takes square roots and trigonometric functions.
 *
 * <p>All other numeric code in the engine is plain {@code float} arithmetic. Keeping these calls
 * here lets other flavours of the engine be generated from the same source: the double-precision
 * flavour (engine-double/README.md) by the generator's type rules alone, a fixed-point one by
 * replacing this class and the number type. Trigonometry goes through {@link StrictMath} so results are
 * bit-identical on every JVM and Android runtime; {@code sqrt} is exactly rounded by IEEE 754.
 */
public final class EMath {
    /** π as a float (a cast of {@link Math#PI}, so the double flavour gets π to its own precision). */
    public static final float PI = (float) Math.PI;
    /** 2π as a float. */
    public static final float TWO_PI = (float) (2 * Math.PI);

    private EMath() {
    }

    /**
     * Square root.
     *
     * @param x a non-negative value
     * @return √x
     */
    public static float sqrt(float x) {
        return (float) Math.sqrt(x);
    }

    /**
     * The length of (x, y) without overflow: x² + y² overflows a float from about 1.8e19, while the
     * length itself is finite whenever x and y are.
     *
     * @param x a finite value
     * @param y a finite value
     * @return √(x² + y²)
     */
    public static float length(float x, float y) {
        float ax = x < 0f ? -x : x;
        float ay = y < 0f ? -y : y;
        float m = ax > ay ? ax : ay;
        if (m == 0f || m < 1e18f) {
            return sqrt(x * x + y * y);
        }
        float sx = ax / m;
        float sy = ay / m;
        return m * sqrt(sx * sx + sy * sy);
    }

    /**
     * Sine.
     *
     * @param radians the angle in radians
     * @return sin(radians)
     */
    public static float sin(float radians) {
        return (float) StrictMath.sin(radians);
    }

    /**
     * Cosine.
     *
     * @param radians the angle in radians
     * @return cos(radians)
     */
    public static float cos(float radians) {
        return (float) StrictMath.cos(radians);
    }

    /**
     * Four-quadrant arc tangent.
     *
     * @param y the ordinate
     * @param x the abscissa
     * @return the angle of (x, y) in radians, in [-π, π]
     */
    public static float atan2(float y, float x) {
        return (float) StrictMath.atan2(y, x);
    }

    /**
     * Whether a value is neither NaN nor infinite.
     *
     * @param x the value
     * @return true when x is a finite number
     */
    public static boolean isFinite(float x) {
        return x - x == 0f;
    }
}
