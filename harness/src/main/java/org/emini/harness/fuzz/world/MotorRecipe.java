package org.emini.harness.fuzz.world;

/** A motor: rotational or linear, its cap as an impulse per tick (the scene's), relative and orthogonal modes. */
public final class MotorRecipe {
    /** Id as generated. */
    public int id;
    /** The driven body's id. */
    public int body;
    /** Rotational (omega) or linear (vx, vy). */
    public boolean rotational;
    /** Target angular velocity (rad/s). */
    public float omega;
    /** Target velocity (px/s). */
    public float vx;
    /** Target velocity (px/s). */
    public float vy;
    /** Cap on the impulse per tick; the engine's force cap is this over the timestep. */
    public float maxImpulse;
    /** Linear target in the body's frame. */
    public boolean relative;
    /** Linear motor also brakes perpendicular motion. */
    public boolean orthogonal;
}
