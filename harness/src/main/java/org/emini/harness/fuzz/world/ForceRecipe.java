package org.emini.harness.fuzz.world;

/** An external force applied every tick ({@link FuzzForce}). */
public final class ForceRecipe {
    /** What it does. */
    public enum Kind {
        /** {@code applyForce(fx, fy)} on one body. */
        force,
        /** {@code applyForceAt(fx, fy)} at the body-local point (px, py), turning with the body. */
        forceAt,
        /** {@code applyTorque(torque)} on one body. */
        torque,
        /** {@code applyAcceleration(fx, fy)} on every dynamic body. */
        wind
    }

    /** Id as generated. */
    public int id;
    /** What it does. */
    public Kind kind = Kind.force;
    /** The body's id (not for wind). */
    public int body = -1;
    /** Force (or acceleration for wind). */
    public float fx;
    /** Force (or acceleration for wind). */
    public float fy;
    /** Body-local point (px). */
    public float px;
    /** Body-local point (px). */
    public float py;
    /** Torque. */
    public float torque;
}
