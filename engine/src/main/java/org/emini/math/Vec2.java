package org.emini.math;

/**
 * A mutable two-dimensional float vector, for the public API and for tests.
 *
 * <p>The simulation itself works on flat float arrays and never allocates vectors while ticking;
 * this class is for users who like to pass points around as objects.
 */
public final class Vec2 {
    /** The x component (px, px/s, ... depending on use). */
    public float x;
    /** The y component; y points down the screen, as in the original engine. */
    public float y;

    /** Creates the zero vector. */
    public Vec2() {
    }

    /**
     * Creates a vector.
     *
     * @param x the x component
     * @param y the y component
     */
    public Vec2(float x, float y) {
        this.x = x;
        this.y = y;
    }

    /**
     * Sets both components.
     *
     * @param x the x component
     * @param y the y component
     * @return this vector
     */
    public Vec2 set(float x, float y) {
        this.x = x;
        this.y = y;
        return this;
    }

    /**
     * Euclidean length.
     *
     * @return |this|
     */
    public float length() {
        return EMath.sqrt(x * x + y * y);
    }

    /**
     * Dot product.
     *
     * @param o the other vector
     * @return this · o
     */
    public float dot(Vec2 o) {
        return x * o.x + y * o.y;
    }

    /**
     * Two-dimensional cross product (the z component of the 3-D cross product).
     *
     * @param o the other vector
     * @return this.x·o.y − this.y·o.x
     */
    public float cross(Vec2 o) {
        return x * o.y - y * o.x;
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof Vec2)) {
            return false;
        }
        Vec2 v = (Vec2) o;
        return Float.floatToIntBits(x) == Float.floatToIntBits(v.x)
            && Float.floatToIntBits(y) == Float.floatToIntBits(v.y);
    }

    @Override
    public int hashCode() {
        return 31 * Float.floatToIntBits(x) + Float.floatToIntBits(y);
    }

    @Override
    public String toString() {
        return "(" + x + ", " + y + ")";
    }
}
