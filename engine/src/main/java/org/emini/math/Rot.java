package org.emini.math;

/**
 * A rotation stored as its cosine and sine.
 *
 * <p>The engine keeps orientations as (cos, sin) pairs and advances them with a short series
 * rather than trigonometry, so the angle itself is only needed at the API boundary.
 * A rotation by angle θ maps a local point (x, y) to (c·x − s·y, s·x + c·y); on a y-down screen a
 * growing angle turns a body clockwise.
 */
public final class Rot {
    /** Cosine of the angle. */
    public float c = 1f;
    /** Sine of the angle. */
    public float s;

    /** Creates the identity rotation. */
    public Rot() {
    }

    /**
     * Creates a rotation from an angle.
     *
     * @param radians the angle in radians
     */
    public Rot(float radians) {
        set(radians);
    }

    /**
     * Sets the rotation to an angle.
     *
     * @param radians the angle in radians
     * @return this rotation
     */
    public Rot set(float radians) {
        c = EMath.cos(radians);
        s = EMath.sin(radians);
        return this;
    }

    /**
     * The angle of this rotation.
     *
     * @return the angle in radians, in [-π, π]
     */
    public float angle() {
        return EMath.atan2(s, c);
    }

    /**
     * Rotates a vector in place.
     *
     * @param v the vector to rotate
     * @return v
     */
    public Vec2 apply(Vec2 v) {
        float x = c * v.x - s * v.y;
        v.y = s * v.x + c * v.y;
        v.x = x;
        return v;
    }

    /**
     * Rotates a vector by the inverse of this rotation, in place.
     *
     * @param v the vector to rotate
     * @return v
     */
    public Vec2 applyInverse(Vec2 v) {
        float x = c * v.x + s * v.y;
        v.y = -s * v.x + c * v.y;
        v.x = x;
        return v;
    }
}
