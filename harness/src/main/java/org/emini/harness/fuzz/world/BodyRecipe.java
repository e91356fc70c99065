package org.emini.harness.fuzz.world;

/** A body: its shape (by id), pose, velocity and flags. */
public final class BodyRecipe {
    /** Id as generated. */
    public int id;
    /** The shape's id. */
    public int shape;
    /** Position (px). */
    public float x;
    /** Position (px). */
    public float y;
    /** Angle (rad). */
    public float angle;
    /** Velocity (px/s). */
    public float vx;
    /** Velocity (px/s). */
    public float vy;
    /** Angular velocity (rad/s). */
    public float omega;
    /** Dynamic or static. */
    public boolean dynamic = true;
    /** Swept against every body, not only static ones. */
    public boolean bullet;
    /** May rotate. */
    public boolean rotatable = true;
    /** Collides with bodies. */
    public boolean interacting = true;
    /** Gravity acts on it. */
    public boolean gravity = true;
    /** Collision layer bits (bodies sharing one do not collide). */
    public int layers;
    /** Box2D's filter: category bits, mask bits, group index (defaults change nothing). */
    public int categories = 1;
    /** Box2D's filter. */
    public int mask = -1;
    /** Box2D's filter. */
    public int group;
    /** A sensor: collides with nothing, reports overlaps. */
    public boolean sensor;
    /** May fall asleep (when the world lets bodies sleep). */
    public boolean sleepingAllowed = true;
}
