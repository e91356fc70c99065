package org.emini.io;

/**
 * A vector of a world file: two raw FX values (12 fractional bits), in px, px/s or px/s² by
 * field. Immutable.
 */
public final class PhyVector {
    /** The zero vector. */
    public static final PhyVector ZERO = new PhyVector(0, 0);

    private final int x;
    private final int y;

    /**
     * Creates a vector from raw FX values.
     *
     * @param xRaw the x component, raw FX
     * @param yRaw the y component, raw FX
     */
    public PhyVector(int xRaw, int yRaw) {
        this.x = xRaw;
        this.y = yRaw;
    }

    /**
     * Creates a vector from engine units, rounding to the nearest FX value.
     *
     * @param x the x component
     * @param y the y component
     * @return the vector
     * @throws IllegalArgumentException if a component is NaN or out of the FX range
     */
    public static PhyVector of(float x, float y) {
        return new PhyVector(PhyFixed.toFx(x), PhyFixed.toFx(y));
    }

    /**
     * The raw x component.
     *
     * @return x · 4096
     */
    public int getXRaw() {
        return x;
    }

    /**
     * The raw y component.
     *
     * @return y · 4096
     */
    public int getYRaw() {
        return y;
    }

    /**
     * The x component in engine units.
     *
     * @return raw x / 4096
     */
    public float getX() {
        return PhyFixed.fx(x);
    }

    /**
     * The y component in engine units (y points down the screen).
     *
     * @return raw y / 4096
     */
    public float getY() {
        return PhyFixed.fx(y);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof PhyVector && ((PhyVector) o).x == x && ((PhyVector) o).y == y;
    }

    @Override
    public int hashCode() {
        return 31 * x + y;
    }

    @Override
    public String toString() {
        return "(" + getX() + ", " + getY() + ")";
    }
}
