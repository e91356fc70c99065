package org.emini.harness.fuzz.world;

/** The simulation area: a rectangle, or the original's x range over the full height. */
public final class AreaRecipe {
    /** Left edge (px). */
    public float minX;
    /** Top edge (px); ignored for an x range. */
    public float minY;
    /** Right edge (px). */
    public float maxX;
    /** Bottom edge (px); ignored for an x range. */
    public float maxY;
    /** True for the x-range form {@code setSimulationArea(start, end)}. */
    public boolean range;
}
