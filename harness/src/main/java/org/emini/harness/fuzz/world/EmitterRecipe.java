package org.emini.harness.fuzz.world;

/** A particle emitter with every setter's value, in the scene's units (angles in degrees). */
public final class EmitterRecipe {
    /** Id as generated. */
    public int id;
    /** The carrying body's id, or -1 for a world-fixed emitter. */
    public int body = -1;
    /** Pool size. */
    public int maxCount = 100;
    /** Emit segment (px; body-local on a body). */
    public float x1;
    /** Emit segment. */
    public float y1;
    /** Emit segment. */
    public float x2;
    /** Emit segment. */
    public float y2;
    /** Particles per second and its spread. */
    public float rate = 20f;
    /** Spread. */
    public float rateSpread;
    /** Seconds and spread. */
    public float lifetime = 2f;
    /** Spread. */
    public float lifetimeSpread;
    /** px/s and spread. */
    public float speed = 10f;
    /** Spread. */
    public float speedSpread;
    /** Direction (degrees) and spread. */
    public float angleDeg;
    /** Spread (degrees). */
    public float angleSpreadDeg;
    /** World-aligned offsets on a body. */
    public boolean axesFixed;
    /** Bounce factor. */
    public float elasticity = 1f;
    /** Gravity factor. */
    public float gravityFactor = 1f;
    /** Velocity fraction lost per tick. */
    public float damping;
    /** Particles bounce off bodies and the landscape. */
    public boolean collide = true;
    /** The emitter's random seed. */
    public long seed;
}
