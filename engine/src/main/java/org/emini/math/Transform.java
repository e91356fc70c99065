package org.emini.math;

/**
 * A rigid transform: a rotation followed by a translation. Maps body-local points to the world.
 */
public final class Transform {
    /** The translation (px). */
    public final Vec2 p = new Vec2();
    /** The rotation. */
    public final Rot q = new Rot();

    /** Creates the identity transform. */
    public Transform() {
    }

    /**
     * Creates a transform.
     *
     * @param x the translation's x (px)
     * @param y the translation's y (px)
     * @param radians the rotation angle
     */
    public Transform(float x, float y, float radians) {
        p.set(x, y);
        q.set(radians);
    }

    /**
     * Maps a local point to the world, in place.
     *
     * @param v the point
     * @return v
     */
    public Vec2 apply(Vec2 v) {
        q.apply(v);
        v.x += p.x;
        v.y += p.y;
        return v;
    }

    /**
     * Maps a world point to local coordinates, in place.
     *
     * @param v the point
     * @return v
     */
    public Vec2 applyInverse(Vec2 v) {
        v.x -= p.x;
        v.y -= p.y;
        return q.applyInverse(v);
    }
}
