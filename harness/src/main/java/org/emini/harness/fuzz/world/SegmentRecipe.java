package org.emini.harness.fuzz.world;

/** A landscape segment with its face (0 none, 1 left, 2 right: the engine's constants). */
public final class SegmentRecipe {
    /** Id as generated. */
    public int id;
    /** Start (px). */
    public float x1;
    /** Start (px). */
    public float y1;
    /** End (px). */
    public float x2;
    /** End (px). */
    public float y2;
    /** Landscape.FACE_NONE, FACE_LEFT or FACE_RIGHT. */
    public int face;
}
