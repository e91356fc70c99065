package org.emini.event;

import org.emini.collision.Collider;
import org.emini.collision.IndexList;
import org.emini.collision.Manifold;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.Contact;
import org.emini.dynamics.CopyMapping;
import org.emini.dynamics.Simulation;
import org.emini.math.EMath;
import org.emini.shape.Shape;

/**
 * A condition the world checks at the end of every tick, telling its
 * {@link PhysicsEventListener} whenever it holds (the original engine's events).
 *
 * <p>Body events (position, velocity, angle, angular velocity, collision, relative collision,
 * sensor) apply to one body, to every body with a given shape, or to every body; constraint-force
 * events to one constraint or to every constraint. The filter is fixed when the event is created.
 * Each tick the listener is called once for every body (or contact, for collisions, or constraint)
 * that meets the condition. With {@link #setTriggerOnce(boolean) trigger-once} each body or
 * constraint is reported only the first time.
 *
 * <p>A body counts as colliding through a contact point that touches: the shapes overlapped when
 * the tick began, or the point carried a normal impulse during the tick (so a body that lands
 * within the tick is reported in that tick). Checking allocates nothing.
 */
public final class Event {
    /** Type: the body's position lies in a rectangle. */
    public static final int POSITION = 0;
    /** Type: the body's speed lies in a range. */
    public static final int VELOCITY = 1;
    /** Type: the body's angle, wrapped to [0, 2π), lies in a range. */
    public static final int ANGLE = 2;
    /** Type: the body's angular velocity lies in a range. */
    public static final int ANGULAR_VELOCITY = 3;
    /** Type: the body touches another body on the enabled sides. */
    public static final int COLLISION = 4;
    /** Type: the body's shape overlaps a sensor body. */
    public static final int SENSOR = 5;
    /** Type: the body touches another body in a range of directions relative to its angle. */
    public static final int RELATIVE_COLLISION = 6;
    /** Type: the force a constraint exerted in the tick lies in a range. */
    public static final int CONSTRAINT_FORCE = 10;

    private final int type;
    private final Body body;
    private final Shape shape;
    private final Constraint constraint;
    private final Body sensor;
    // The condition's numbers; their meaning depends on the type (see the factories).
    private final float t1;
    private final float t2;
    private final float t3;
    private final float t4;
    private boolean triggerOnce;
    private Object userData;
    private Script script;
    private final IdentitySet reported = new IdentitySet();
    // Scratch, so checking allocates nothing: a body's contacts, and the sensor's overlap test.
    private Contact[] contacts;
    private final Collider collider;
    private final Manifold manifold;
    private final float[] box;
    private final float[] otherBox;
    private final IndexList near;

    private Event(int type, Body body, Shape shape, Constraint constraint, Body sensor,
            float t1, float t2, float t3, float t4) {
        this.type = type;
        this.body = body;
        this.shape = shape;
        this.constraint = constraint;
        this.sensor = sensor;
        this.t1 = t1;
        this.t2 = t2;
        this.t3 = t3;
        this.t4 = t4;
        boolean sensing = type == SENSOR;
        collider = sensing ? new Collider() : null;
        manifold = sensing ? new Manifold() : null;
        box = sensing ? new float[4] : null;
        otherBox = sensing ? new float[4] : null;
        near = sensing ? new IndexList() : null;
        contacts = type == COLLISION || type == RELATIVE_COLLISION ? new Contact[4] : null;
    }

    // ---------------------------------------------------------------------------------------------
    // Factories

    /**
     * An event that holds while a body's position (its origin) lies in a rectangle, edges
     * included.
     *
     * @param body the body, or null for every body
     * @param shape only bodies with this very shape object, or null for any shape
     * @param minX left edge (px)
     * @param minY top edge (px)
     * @param maxX right edge (px), &ge; minX
     * @param maxY bottom edge (px), &ge; minY
     * @return the event
     */
    public static Event createPositionEvent(Body body, Shape shape, float minX, float minY, float maxX, float maxY) {
        range("Event.createPositionEvent", "minX", minX, "maxX", maxX);
        range("Event.createPositionEvent", "minY", minY, "maxY", maxY);
        return new Event(POSITION, body, shape, null, null, minX, minY, maxX, maxY);
    }

    /**
     * An event that holds while a body's speed lies in a range, ends included.
     *
     * @param body the body, or null for every body
     * @param shape only bodies with this very shape object, or null for any shape
     * @param minSpeed the lowest speed (px/s), &ge; 0
     * @param maxSpeed the highest speed (px/s), &ge; minSpeed; may be infinite
     * @return the event
     */
    public static Event createVelocityEvent(Body body, Shape shape, float minSpeed, float maxSpeed) {
        range("Event.createVelocityEvent", "minSpeed", minSpeed, "maxSpeed", maxSpeed);
        if (minSpeed < 0f) {
            throw new IllegalArgumentException("Event.createVelocityEvent: minSpeed must be >= 0, was " + minSpeed);
        }
        // Compared as squares, so no square root per body and tick.
        return new Event(VELOCITY, body, shape, null, null, minSpeed * minSpeed, maxSpeed * maxSpeed, 0f, 0f);
    }

    /**
     * An event that holds while a body's angle, wrapped to [0, 2π), lies in a range, ends
     * included.
     *
     * @param body the body, or null for every body
     * @param shape only bodies with this very shape object, or null for any shape
     * @param minAngle the lowest angle (rad)
     * @param maxAngle the highest angle (rad), &ge; minAngle
     * @return the event
     */
    public static Event createAngleEvent(Body body, Shape shape, float minAngle, float maxAngle) {
        range("Event.createAngleEvent", "minAngle", minAngle, "maxAngle", maxAngle);
        return new Event(ANGLE, body, shape, null, null, minAngle, maxAngle, 0f, 0f);
    }

    /**
     * An event that holds while a body's angular velocity lies in a range, ends included.
     *
     * @param body the body, or null for every body
     * @param shape only bodies with this very shape object, or null for any shape
     * @param min the lowest angular velocity (rad/s)
     * @param max the highest angular velocity (rad/s), &ge; min
     * @return the event
     */
    public static Event createAngularVelocityEvent(Body body, Shape shape, float min, float max) {
        range("Event.createAngularVelocityEvent", "min", min, "max", max);
        return new Event(ANGULAR_VELOCITY, body, shape, null, null, min, max, 0f, 0f);
    }

    /**
     * An event that holds while a body touches another body at a contact point above, right of,
     * below or left of the body's position (each side enabled separately, as in the original
     * engine). The listener gets the contact; a contact is reported once per tick.
     *
     * @param body the body, or null for every body
     * @param shape only bodies with this very shape object, or null for any shape
     * @param above report points with a smaller y than the body's
     * @param right report points with a larger x
     * @param below report points with a larger y
     * @param left report points with a smaller x
     * @return the event
     */
    public static Event createCollisionEvent(Body body, Shape shape, boolean above, boolean right, boolean below, boolean left) {
        return new Event(COLLISION, body, shape, null, null, flag(above), flag(right), flag(below), flag(left));
    }

    /**
     * An event that holds while a body touches another body at a contact point whose direction,
     * seen from the body's position and measured from the body's own angle, lies between two
     * angles. Angles grow clockwise on the y-down screen, like body angles: with the body at angle
     * 0, π/2 is straight down, so the range [π/4, 3π/4] reports the body standing on something.
     * (The original engine measures the opposite direction, from the point to the body: its angle
     * is this one plus π.) The listener gets the contact.
     *
     * @param body the body, or null for every body
     * @param shape only bodies with this very shape object, or null for any shape
     * @param startAngle where the range begins (rad)
     * @param endAngle where it ends (rad), from startAngle to startAngle + 2π
     * @return the event
     */
    public static Event createRelativeCollisionEvent(Body body, Shape shape, float startAngle, float endAngle) {
        range("Event.createRelativeCollisionEvent", "startAngle", startAngle, "endAngle", endAngle);
        if (!EMath.isFinite(startAngle) || !EMath.isFinite(endAngle) || endAngle - startAngle > EMath.TWO_PI) {
            throw new IllegalArgumentException("Event.createRelativeCollisionEvent: the range must be finite and at most 2π wide, was "
                + startAngle + " to " + endAngle);
        }
        float centre = 0.5f * (startAngle + endAngle);
        float halfWidth = 0.5f * (endAngle - startAngle);
        return new Event(RELATIVE_COLLISION, body, shape, null, null,
            EMath.cos(centre), EMath.sin(centre), EMath.cos(halfWidth), 0f);
    }

    /**
     * An event that holds while a body's shape overlaps a sensor body's shape. The sensor may be
     * a body that is not in the world (it is only used for its shape and pose), or one that is,
     * made static or non-interacting so it does not collide. Without a body filter only dynamic
     * bodies are tested, as in the original engine.
     *
     * @param body the body, or null for every dynamic body
     * @param shape only bodies with this very shape object, or null for any shape
     * @param sensor the sensor body
     * @return the event
     */
    public static Event createSensorEvent(Body body, Shape shape, Body sensor) {
        if (sensor == null) {
            throw new IllegalArgumentException("Event.createSensorEvent: sensor must not be null");
        }
        if (sensor == body) {
            throw new IllegalArgumentException("Event.createSensorEvent: the body cannot be its own sensor");
        }
        return new Event(SENSOR, body, shape, null, sensor, 0f, 0f, 0f, 0f);
    }

    /**
     * An event that holds while the force a constraint exerted in the last tick
     * ({@link Constraint#getForce()}) lies in a range, ends included.
     *
     * @param constraint the constraint, or null for every constraint
     * @param minForce the lowest force
     * @param maxForce the highest force, &ge; minForce; may be infinite
     * @return the event
     */
    public static Event createConstraintForceEvent(Constraint constraint, float minForce, float maxForce) {
        range("Event.createConstraintForceEvent", "minForce", minForce, "maxForce", maxForce);
        return new Event(CONSTRAINT_FORCE, null, null, constraint, null, minForce, maxForce, 0f, 0f);
    }

    private static void range(String where, String minName, float min, String maxName, float max) {
        // Also refuses NaN, for which every comparison is false.
        if (!(min <= max)) {
            throw new IllegalArgumentException(where + ": " + minName + " must be <= " + maxName + " (and not NaN), was "
                + min + " and " + max);
        }
    }

    private static float flag(boolean on) {
        return on ? 1f : 0f;
    }

    // ---------------------------------------------------------------------------------------------
    // Properties

    /**
     * The event's type: one of the constants of this class.
     *
     * @return the type
     */
    public int getType() {
        return type;
    }

    /**
     * The body the event is restricted to.
     *
     * @return the body, or null for every body
     */
    public Body getBody() {
        return body;
    }

    /**
     * The shape the event's bodies must have.
     *
     * @return the shape, or null for any shape
     */
    public Shape getShape() {
        return shape;
    }

    /**
     * The constraint a constraint-force event is restricted to.
     *
     * @return the constraint, or null for every constraint (or a body event)
     */
    public Constraint getConstraint() {
        return constraint;
    }

    /**
     * The sensor body of a sensor event.
     *
     * @return the sensor, or null for other types
     */
    public Body getSensor() {
        return sensor;
    }

    /**
     * Whether each body or constraint is reported only the first time.
     *
     * @return true in trigger-once mode (default false)
     */
    public boolean isTriggerOnce() {
        return triggerOnce;
    }

    /**
     * Reports each body or constraint only the first time its condition holds, or every tick.
     *
     * @param once true for trigger-once
     */
    public void setTriggerOnce(boolean once) {
        triggerOnce = once;
    }

    /**
     * A copy of this event for a copied world: the same condition, trigger-once setting and user
     * data, on the copies of its body, sensor body (a sensor outside the world stays shared) and
     * constraint; nothing reported yet.
     *
     * @param mapping the copies of the world's bodies and constraints
     * @return the copy, not in any world
     */
    public Event copy(CopyMapping mapping) {
        Event copy = new Event(type, body == null ? null : mapping.body(body), shape,
            constraint == null ? null : mapping.constraint(constraint), sensor == null ? null : mapping.body(sensor),
            t1, t2, t3, t4);
        copy.triggerOnce = triggerOnce;
        copy.userData = userData;
        copy.script = script;
        return copy;
    }

    /**
     * Attaches a script, the original's {@code Event.setScript}: while the condition holds for a
     * body, the world starts the script on that body instead of telling the listener (events are
     * checked only while a listener is set, as in the original). Constraint events have no body and
     * still tell the listener.
     *
     * @param script the script, or null to tell the listener again
     */
    public void setScript(Script script) {
        this.script = script;
    }

    /**
     * The script the event starts.
     *
     * @return the script, or null
     */
    public Script getScript() {
        return script;
    }

    /** Forgets what a trigger-once event has reported, so everything may be reported again. */
    public void reset() {
        reported.clear();
    }

    /**
     * The application's object attached to this event.
     *
     * @return the user data, or null
     */
    public Object getUserData() {
        return userData;
    }

    /**
     * Attaches an application object to this event.
     *
     * @param userData any object, or null
     */
    public void setUserData(Object userData) {
        this.userData = userData;
    }

    // ---------------------------------------------------------------------------------------------
    // Checking

    /**
     * Tests the condition on the world as it is now and calls the listener for each body, contact
     * or constraint that meets it. The world does this at the end of every tick while it has a
     * listener; calling it yourself tests again (and counts for trigger-once).
     *
     * @param world the world
     * @param listener the listener to tell
     */
    public void check(Simulation world, PhysicsEventListener listener) {
        if (listener == null) {
            throw new IllegalArgumentException("Event.check: listener must not be null");
        }
        switch (type) {
            case CONSTRAINT_FORCE:
                checkConstraints(world, listener);
                break;
            case COLLISION:
            case RELATIVE_COLLISION:
                if (body != null) {
                    checkContactsOf(body, world, listener);
                } else {
                    checkAllContacts(world, listener);
                }
                break;
            default:
                if (body != null) {
                    if (body.getWorld() == world && wanted(body) && holds(body)) {
                        fire(world, body, body, listener);
                    }
                } else if (type == SENSOR) {
                    checkBodiesAtSensor(world, listener);
                } else {
                    for (int i = 0, n = world.getBodyCount(); i < n; i++) {
                        Body b = world.getBody(i);
                        if (wanted(b) && holds(b)) {
                            fire(world, b, b, listener);
                        }
                    }
                }
                break;
        }
    }

    /** The bodies whose boxes meet the sensor's, from the broadphase: the rest of the world costs nothing. */
    private void checkBodiesAtSensor(Simulation world, PhysicsEventListener listener) {
        float[] sb = box;
        sensor.getShape().computeAabb(sensor.getX(), sensor.getY(), sensor.getCos(), sensor.getSin(), sb);
        near.clear();
        world.queryBodies(sb[0], sb[1], sb[2], sb[3], near);
        for (int j = 0, n = near.count(); j < n; j++) {
            Body b = world.getBody(near.get(j));
            if (wanted(b) && holds(b)) {
                fire(world, b, b, listener);
            }
        }
    }

    private void checkConstraints(Simulation world, PhysicsEventListener listener) {
        for (int i = 0, n = world.getConstraintCount(); i < n; i++) {
            Constraint c = world.getConstraint(i);
            if (constraint != null && c != constraint) {
                continue;
            }
            float f = c.getForce();
            if (f >= t1 && f <= t2 && !(triggerOnce && reported.contains(c))) {
                fire(world, c, c, listener);
            }
        }
    }

    private void checkContactsOf(Body b, Simulation world, PhysicsEventListener listener) {
        if (b.getWorld() != world || !wanted(b)) {
            return;
        }
        int n = b.getContactCount();
        if (contacts.length < n) {
            contacts = new Contact[Math.max(n, 2 * contacts.length)];
        }
        n = b.getContacts(contacts);
        for (int k = 0; k < n && wanted(b); k++) {
            if (touches(contacts[k], b)) {
                fire(world, b, contacts[k], listener);
            }
        }
    }

    private void checkAllContacts(Simulation world, PhysicsEventListener listener) {
        for (int i = 0, n = world.getContactCount(); i < n; i++) {
            Contact c = world.getContact(i);
            Body a = c.getBodyA();
            Body b = c.getBodyB();
            // One report per contact: body A's side first. A landscape contact has no body B.
            if (wanted(a) && touches(c, a)) {
                fire(world, a, c, listener);
            } else if (b != null && wanted(b) && touches(c, b)) {
                fire(world, b, c, listener);
            }
        }
    }

    /** Passes the shape filter and, in trigger-once mode, has not been reported yet. */
    private boolean wanted(Body b) {
        return (shape == null || b.getShape() == shape) && !(triggerOnce && reported.contains(b));
    }

    private void fire(Simulation world, Object key, Object parameter, PhysicsEventListener listener) {
        if (triggerOnce) {
            reported.add(key);
        }
        if (script != null && key instanceof Body && world instanceof ScriptHost) {
            // The original starts the script on the body instead of telling the listener.
            ((ScriptHost) world).applyScript(script, (Body) key);
        } else {
            listener.eventTriggered(this, parameter);
        }
    }

    private boolean holds(Body b) {
        switch (type) {
            case POSITION: {
                float x = b.getX();
                float y = b.getY();
                return x >= t1 && x <= t3 && y >= t2 && y <= t4;
            }
            case VELOCITY: {
                float vx = b.getVelocityX();
                float vy = b.getVelocityY();
                float v2 = vx * vx + vy * vy;
                return v2 >= t1 && v2 <= t2;
            }
            case ANGLE: {
                float a = b.getAngle() % EMath.TWO_PI;
                if (a < 0f) {
                    a += EMath.TWO_PI;
                }
                if (a >= EMath.TWO_PI) {
                    a = 0f;
                }
                return a >= t1 && a <= t2;
            }
            case ANGULAR_VELOCITY: {
                float w = b.getAngularVelocity();
                return w >= t1 && w <= t2;
            }
            case SENSOR:
                return b != sensor && (body != null || b.isDynamic()) && overlapsSensor(b);
            default:
                return false;
        }
    }

    /** Whether a contact of body b has a touching point on one of the enabled sides. */
    private boolean touches(Contact c, Body b) {
        float x = b.getX();
        float y = b.getY();
        for (int i = 0, n = c.getPointCount(); i < n; i++) {
            if (c.getSeparation(i) > 0f && c.getNormalImpulse(i) <= 0f && c.getMaxNormalImpulse(i) <= 0f) {
                continue;
            }
            float px = c.getPointX(i) - x;
            float py = c.getPointY(i) - y;
            if (type == COLLISION) {
                if ((t1 != 0f && py < 0f) || (t2 != 0f && px > 0f) || (t3 != 0f && py > 0f) || (t4 != 0f && px < 0f)) {
                    return true;
                }
            } else {
                // The range's centre direction turned with the body, against the point's direction.
                float dx = b.getCos() * t1 - b.getSin() * t2;
                float dy = b.getSin() * t1 + b.getCos() * t2;
                float length = EMath.sqrt(px * px + py * py);
                if (length > 0f && px * dx + py * dy >= t3 * length) {
                    return true;
                }
            }
        }
        return false;
    }

    private boolean overlapsSensor(Body b) {
        float[] sb = box;
        float[] bb = otherBox;
        Shape ss = sensor.getShape();
        float sx = sensor.getX();
        float sy = sensor.getY();
        float sc = sensor.getCos();
        float sn = sensor.getSin();
        ss.computeAabb(sx, sy, sc, sn, sb);
        Shape bs = b.getShape();
        bs.computeAabb(b.getX(), b.getY(), b.getCos(), b.getSin(), bb);
        if (bb[0] > sb[2] || bb[2] < sb[0] || bb[1] > sb[3] || bb[3] < sb[1]) {
            return false;
        }
        return collider.overlaps(ss, sx, sy, sc, sn, bs, b.getX(), b.getY(), b.getCos(), b.getSin(), manifold);
    }

    @Override
    public String toString() {
        return "Event(type " + type + (body != null ? ", " + body : "") + (constraint != null ? ", " + constraint : "")
            + (triggerOnce ? ", once" : "") + ")";
    }
}
