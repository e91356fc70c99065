package org.emini.shape;

import org.emini.math.EMath;

/**
 * A solid disc. Its centre is usually the local origin; an offset centre is allowed (parts of a
 * multi-shape need it), in which case the body rotates about the origin, not the centre.
 */
public final class Circle extends Shape {
    private final float radius;
    private final float centerX;
    private final float centerY;

    /**
     * Creates a circle centred on the local origin.
     *
     * @param radius the radius (px), finite and at least {@link Shape#MIN_SIZE} / 2
     * @throws InvalidShapeException if the radius is not finite, not positive or too small
     */
    public Circle(float radius) {
        this(radius, 0f, 0f);
    }

    /**
     * Creates a circle whose centre is offset from the local origin. Its inertia about the origin
     * is m·r²/2 + m·|centre|².
     *
     * @param radius the radius (px), finite and at least {@link Shape#MIN_SIZE} / 2
     * @param centerX the centre's local x (px), finite
     * @param centerY the centre's local y (px), finite
     * @throws InvalidShapeException if a value is not finite or the radius is not positive or too
     *     small
     */
    public Circle(float radius, float centerX, float centerY) {
        super(validated(radius, centerX, centerY), TYPE_CIRCLE);
        this.radius = radius;
        this.centerX = centerX;
        this.centerY = centerY;
    }

    private static ShapeGeometry validated(float radius, float centerX, float centerY) {
        if (!EMath.isFinite(radius) || !EMath.isFinite(centerX) || !EMath.isFinite(centerY)) {
            throw new InvalidShapeException(InvalidShapeException.Rule.NOT_FINITE, -1,
                    "Circle: rule NOT_FINITE: radius " + radius + " and centre (" + centerX + ", "
                            + centerY + ") must be finite");
        }
        if (!(radius > 0f)) {
            throw new InvalidShapeException(InvalidShapeException.Rule.DEGENERATE, -1,
                    "Circle: rule DEGENERATE: radius must be > 0, got " + radius);
        }
        if (2f * radius < MIN_SIZE) {
            throw new InvalidShapeException(InvalidShapeException.Rule.TOO_SMALL, -1,
                    "Circle: rule TOO_SMALL: radius " + radius + " px makes a diameter below Shape.MIN_SIZE ("
                            + MIN_SIZE + " px)");
        }
        return ShapeGeometry.ofCircle(radius, centerX, centerY);
    }

    /**
     * The radius.
     *
     * @return the radius (px)
     */
    public float getRadius() {
        return radius;
    }

    /**
     * The local x of the centre.
     *
     * @return the centre's x (px)
     */
    public float getCenterX() {
        return centerX;
    }

    /**
     * The local y of the centre.
     *
     * @return the centre's y (px)
     */
    public float getCenterY() {
        return centerY;
    }

    @Override
    Circle translated(float dx, float dy) {
        Circle c = new Circle(radius, centerX + dx, centerY + dy);
        c.copyMaterial(this);
        return c;
    }

    @Override
    public void computeAabb(float x, float y, float c, float s, float[] out) {
        float wx = x + c * centerX - s * centerY;
        float wy = y + s * centerX + c * centerY;
        out[0] = wx - radius;
        out[1] = wy - radius;
        out[2] = wx + radius;
        out[3] = wy + radius;
    }

    @Override
    public String toString() {
        return "Circle[radius " + radius + ", centre (" + centerX + ", " + centerY + "), mass "
                + getMass() + "]";
    }
}
