package org.emini.harness.fuzz.world;

/** A pin (loose) or fixed joint: at one world point, or at two body-local anchors (maybe apart). */
public final class JointRecipe {
    /** Id as generated. */
    public int id;
    /** Body A's id. */
    public int a;
    /** Body B's id. */
    public int b;
    /** True: {@code Joint.atWorldPoint(x, y)}; false: local anchors. */
    public boolean atPoint;
    /** World point (px). */
    public float x;
    /** World point (px). */
    public float y;
    /** A's local anchor (px). */
    public float ax;
    /** A's local anchor (px). */
    public float ay;
    /** B's local anchor (px). */
    public float bx;
    /** B's local anchor (px). */
    public float by;
    /** Locks the relative angle. */
    public boolean fixed;
    /** Let the two bodies collide; false gives them a shared layer as the harness does (31 − index). */
    public boolean collide;
}
