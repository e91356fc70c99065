package org.emini.harness.fuzz.world;

/** A spring: rigid (no stiffness), Hooke (stiffness and damping) or tuned by frequency. */
public final class SpringRecipe {
    /** Id as generated. */
    public int id;
    /** Body A's id. */
    public int a;
    /** Body B's id. */
    public int b;
    /** A's local anchor (px). */
    public float ax;
    /** A's local anchor (px). */
    public float ay;
    /** B's local anchor (px). */
    public float bx;
    /** B's local anchor (px). */
    public float by;
    /** Rest length (px); negative: the anchors' distance at creation. */
    public float restLength = -1f;
    /** Hooke coefficient (force/px); 0 is a rigid link. */
    public float stiffness;
    /** Damping (force per px/s), with a stiffness. */
    public float damping;
    /** Natural frequency (Hz); above 0 uses {@code setFrequency} instead of a stiffness. */
    public float hertz;
    /** Damping ratio with a frequency. */
    public float dampingRatio;
    /** Let the two bodies collide; false gives them a shared layer as the harness does (index). */
    public boolean collide = true;
}
