package org.emini.collision;

/**
 * A box swept along a translation, as a query of the trees: a ray is a point swept, a shape cast
 * the shape's box swept. {@link #meets} tells whether the box, moved by t·(dx, dy) for some t in
 * [0, 1], overlaps another box (touching counts), with the other box grown by a few float
 * roundings of the coordinates involved, so that the answer errs towards yes: a tree pruned by it
 * never drops what an exact test of the swept shape would hit. A reusable flat struct: set it and
 * pass it; nothing is allocated.
 */
public final class SweptBox {
    /** Rounding allowance, relative to the size of the coordinates. */
    private static final float PAD = 1e-6f;

    private float minX;
    private float minY;
    private float maxX;
    private float maxY;
    private float dx;
    private float dy;
    private float pad;

    /** Creates a sweep of the point (0, 0) by nothing. */
    public SweptBox() {
    }

    /**
     * Sets the box and the translation.
     *
     * @param minX the box's left at the start (px)
     * @param minY its top (px)
     * @param maxX its right (px), &ge; minX
     * @param maxY its bottom (px), &ge; minY
     * @param dx the translation's x (px)
     * @param dy the translation's y (px)
     * @return this sweep
     */
    public SweptBox set(float minX, float minY, float maxX, float maxY, float dx, float dy) {
        this.minX = minX;
        this.minY = minY;
        this.maxX = maxX;
        this.maxY = maxY;
        this.dx = dx;
        this.dy = dy;
        pad = PAD * (Math.abs(minX) + Math.abs(minY) + Math.abs(maxX) + Math.abs(maxY) + Math.abs(dx) + Math.abs(dy));
        return this;
    }

    /** @return the left of the box covering the whole sweep (px), padded */
    public float boundMinX() {
        return Math.min(minX, minX + dx) - pad;
    }

    /** @return the top of the box covering the whole sweep (px), padded */
    public float boundMinY() {
        return Math.min(minY, minY + dy) - pad;
    }

    /** @return the right of the box covering the whole sweep (px), padded */
    public float boundMaxX() {
        return Math.max(maxX, maxX + dx) + pad;
    }

    /** @return the bottom of the box covering the whole sweep (px), padded */
    public float boundMaxY() {
        return Math.max(maxY, maxY + dy) + pad;
    }

    /**
     * Whether the swept box meets another box (grown by the rounding allowance).
     *
     * @param bMinX the other box's left (px)
     * @param bMinY its top (px)
     * @param bMaxX its right (px)
     * @param bMaxY its bottom (px)
     * @return true when the box, somewhere along the sweep, overlaps or touches it
     */
    public boolean meets(float bMinX, float bMinY, float bMaxX, float bMaxY) {
        float lo = 0f;
        float hi = 1f;
        // Per axis, the t where [min + t·d, max + t·d] overlaps [bMin − pad, bMax + pad].
        for (int axis = 0; axis < 2; axis++) {
            float qMin = axis == 0 ? minX : minY;
            float qMax = axis == 0 ? maxX : maxY;
            float d = axis == 0 ? dx : dy;
            float low = (axis == 0 ? bMinX : bMinY) - pad;
            float high = (axis == 0 ? bMaxX : bMaxY) + pad;
            if (d == 0f) {
                if (qMin > high || low > qMax) {
                    return false;
                }
                continue;
            }
            float enter = (low - qMax) / d;
            float leave = (high - qMin) / d;
            if (d < 0f) {
                float swap = enter;
                enter = leave;
                leave = swap;
            }
            lo = Math.max(lo, enter);
            hi = Math.min(hi, leave);
            if (lo > hi) {
                return false;
            }
        }
        return true;
    }

    @Override
    public String toString() {
        return "SweptBox[(" + minX + ", " + minY + ") to (" + maxX + ", " + maxY + ") by (" + dx + ", " + dy + ")]";
    }
}
