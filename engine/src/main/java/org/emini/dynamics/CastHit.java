package org.emini.dynamics;

/**
 * A hit of a ray or a swept shape: what was hit (a body and the part of its shape, or a landscape
 * segment), where, the surface normal there, and how far along the cast. Filled by
 * {@link Simulation#rayCastClosest} and {@link Simulation#castShapeClosest} into an object the
 * caller keeps and reuses, and handed to a {@link CastCallback} for each hit of
 * {@link Simulation#rayCast} and {@link Simulation#castShape} (that one belongs to the world and
 * is valid only during the call: {@link #set(CastHit) copy} what you keep).
 */
public final class CastHit {
    private boolean hit;
    private Body body;
    private int part;
    private int segment = -1;
    private float x;
    private float y;
    private float normalX;
    private float normalY;
    private float fraction;

    /** Creates an empty result (no hit). */
    public CastHit() {
    }

    /**
     * Whether this holds a hit. After a cast that found nothing, false and the other getters give
     * no body, segment −1 and zeros.
     *
     * @return true when something was hit
     */
    public boolean hasHit() {
        return hit;
    }

    /**
     * The body hit.
     *
     * @return the body, or null for a landscape segment (or no hit)
     */
    public Body getBody() {
        return body;
    }

    /**
     * The part of the body's shape hit: its index in a {@link org.emini.shape.MultiShape}, 0 for
     * other shapes and for segments (as {@link Contact#getPartA()} counts parts).
     *
     * @return the part index
     */
    public int getPart() {
        return part;
    }

    /**
     * The landscape segment hit, by its index in the world's {@link Landscape}.
     *
     * @return the segment index, or −1 when a body was hit (or nothing)
     */
    public int getSegment() {
        return segment;
    }

    /**
     * The x of the hit point: where the ray meets the surface; for a swept shape, where it touches
     * the surface at the moment of contact.
     *
     * @return x (px)
     */
    public float getX() {
        return x;
    }

    /**
     * The y of the hit point.
     *
     * @return y (px)
     */
    public float getY() {
        return y;
    }

    /**
     * The x of the unit normal of the surface hit, pointing out of it towards the ray's start or
     * the swept shape.
     *
     * @return the normal's x
     */
    public float getNormalX() {
        return normalX;
    }

    /**
     * The y of the unit normal of the surface hit.
     *
     * @return the normal's y
     */
    public float getNormalY() {
        return normalY;
    }

    /**
     * How far along the cast the hit is: the point is start + fraction · (end − start) for a ray;
     * a swept shape touches after fraction · its translation.
     *
     * @return the fraction, in [0, 1]
     */
    public float getFraction() {
        return fraction;
    }

    /** Forgets the hit. */
    public void clear() {
        hit = false;
        body = null;
        part = 0;
        segment = -1;
        x = 0f;
        y = 0f;
        normalX = 0f;
        normalY = 0f;
        fraction = 0f;
    }

    /**
     * Copies another result into this one.
     *
     * @param other the result to copy
     * @return this result
     */
    public CastHit set(CastHit other) {
        hit = other.hit;
        body = other.body;
        part = other.part;
        segment = other.segment;
        x = other.x;
        y = other.y;
        normalX = other.normalX;
        normalY = other.normalY;
        fraction = other.fraction;
        return this;
    }

    void set(Body b, int p, int s, float hx, float hy, float nx, float ny, float f) {
        hit = true;
        body = b;
        part = p;
        segment = s;
        x = hx;
        y = hy;
        normalX = nx;
        normalY = ny;
        fraction = f;
    }

    @Override
    public String toString() {
        if (!hit) {
            return "CastHit[none]";
        }
        return "CastHit[" + (body != null ? body + " part " + part : "segment " + segment) + " at (" + x + ", " + y
            + "), normal (" + normalX + ", " + normalY + "), fraction " + fraction + "]";
    }
}
