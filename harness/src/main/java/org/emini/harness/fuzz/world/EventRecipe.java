package org.emini.harness.fuzz.world;

/**
 * An event of one of the engine's kinds ({@code org.emini.event.Event} constants), with its filters
 * and its four numbers (their meaning is the factory's: a range, a rectangle or four sides).
 */
public final class EventRecipe {
    /** Id as generated. */
    public int id;
    /** Event.POSITION, VELOCITY, ANGLE, ANGULAR_VELOCITY, COLLISION, SENSOR, RELATIVE_COLLISION or CONSTRAINT_FORCE. */
    public int type;
    /** Only this body (id), or -1 for any. */
    public int body = -1;
    /** Only bodies with this shape (id), or -1 for any. */
    public int shape = -1;
    /** The sensor body (id) of a sensor event. */
    public int sensor = -1;
    /** A constraint-force event's constraint: "joint", "spring" or "motor" with its id; null for any. */
    public String constraintKind;
    /** The constraint's id. */
    public int constraint = -1;
    /** The factory's numbers, in its order (collision: non-zero for above, right, below, left). */
    public float p1;
    /** See p1. */
    public float p2;
    /** See p1. */
    public float p3;
    /** See p1. */
    public float p4;
    /** Report each body once. */
    public boolean triggerOnce;
}
