package org.emini.dynamics;

import org.emini.collision.BroadPhase;
import org.emini.collision.QueryCallback;
import org.emini.event.Event;
import org.emini.event.PhysicsEventListener;
import org.emini.internal.Check;
import org.emini.particle.ParticleEmitter;
import org.emini.particle.ParticleSystem;

/**
 * The simulated world: bodies, gravity, the solver's settings, and {@link #tick()}.
 *
 * <p>Defaults are the original engine's: 20 ticks per second, 10 iterations, gravity (0, 100) px/s²
 * pointing down the screen, no damping. Change bodies and settings only between ticks.
 *
 * <p>One tick: find the bodies to simulate (all dynamic bodies, or those inside the
 * {@linkplain #setSimulationArea(float, float, float, float) simulation area}); update the
 * broadphase and create contacts for pairs that came close and for bodies near segments of the
 * {@link Landscape}; run the narrowphase on the simulated bodies' contacts; then solve. The solver splits the tick into substeps, one per
 * iteration: each substep integrates velocities, warm-starts, makes one soft (position-correcting)
 * pass over the contacts, integrates positions and makes one rigid relax pass. A restitution pass
 * ends the tick. In dynamic-iteration mode the solver stops solving once a relax pass changes no
 * velocity by more than {@link SolverSettings#getConvergenceTolerance()}: the remaining substeps
 * only integrate, re-applying the converged impulses (warm start) so resting stacks stay put.
 *
 * <p>A tick allocates nothing once the world's arrays have grown to the scene, and the same world
 * with the same inputs gives bit-identical results.
 */
public final class World {
    private float timestep = 1f / 20f;
    private int iterations = 10;
    private boolean dynamicIterations;
    private float gravityX;
    private float gravityY = 100f;
    private float dampingLateral;
    private float dampingRotational;
    private final SolverSettings settings = new SolverSettings();

    private Body[] bodies = new Body[16];
    private int bodyCount;
    private Body[] slots = new Body[16];
    private int[] freeSlots = new int[16];
    private int freeSlotCount;
    private int slotHigh;
    private int nextBodyId;

    private final BroadPhase broadPhase;
    private final ContactManager contacts = new ContactManager(this);
    private final SolverBodies solverBodies = new SolverBodies();
    private final ContactSolver contactSolver = new ContactSolver();
    private final SolverStep step = new SolverStep(solverBodies, this);
    private final ContinuousSolver continuous = new ContinuousSolver(this);
    private Constraint[] constraints = new Constraint[8];
    private int constraintCount;
    private ExternalForce[] forces = new ExternalForce[4];
    private int forceCount;
    private Event[] events = new Event[4];
    private int eventCount;
    private PhysicsEventListener eventListener;
    private final ParticleSystem particles = new ParticleSystem();
    private final Softness soft = new Softness();
    private final Softness staticSoft = new Softness();
    private final float[] aabb = new float[4];
    private Landscape landscape = new Landscape();
    private final SimulationArea area = new SimulationArea();
    private final BodyQuery bodyQuery = new BodyQuery();
    // Bodies whose pose or shape the application changed since the last tick.
    private Body[] dirtyBodies = new Body[16];
    private int dirtyCount;
    private float lastSubstep;
    private int lastIterationCount;
    private long tickCount;

    /** Creates an empty world with the original engine's defaults. */
    public World() {
        broadPhase = new BroadPhase(settings.getAabbMargin());
    }

    // ---------------------------------------------------------------------------------------------
    // Settings

    /**
     * The length of one tick.
     *
     * @return the timestep (s)
     */
    public float getTimestep() {
        return timestep;
    }

    /**
     * Sets the length of one tick.
     *
     * @param seconds the timestep (s), &gt; 0
     */
    public void setTimestep(float seconds) {
        timestep = Check.positive("World.setTimestep", "seconds", seconds);
    }

    /**
     * Sets the tick rate (the original engine's default is 20).
     *
     * @param ticksPerSecond the rate (1/s), &gt; 0
     */
    public void setTicksPerSecond(float ticksPerSecond) {
        setTimestep(1f / Check.positive("World.setTicksPerSecond", "ticksPerSecond", ticksPerSecond));
    }

    /**
     * The solver's effort per tick: the number of substeps (each a soft solve and a relax pass).
     *
     * @return the iteration count
     */
    public int getConstraintIterations() {
        return iterations;
    }

    /**
     * Sets the solver's effort per tick (default 10). In dynamic mode this is the maximum.
     *
     * @param iterations the count, 1 to 1000
     */
    public void setConstraintIterations(int iterations) {
        if (iterations < 1 || iterations > 1000) {
            throw new IllegalArgumentException("World.setConstraintIterations: iterations must be in 1..1000, was " + iterations);
        }
        this.iterations = iterations;
    }

    /**
     * Whether the iteration count is dynamic.
     *
     * @return true in dynamic mode
     */
    public boolean isConstraintIterationDynamic() {
        return dynamicIterations;
    }

    /**
     * Lets the solver stop early once it has converged (dynamic mode) or always run all iterations.
     *
     * @param dynamic true for dynamic mode
     */
    public void setConstraintIterationDynamic(boolean dynamic) {
        dynamicIterations = dynamic;
    }

    /**
     * The number of iterations (substeps) the last tick used.
     *
     * @return the count
     */
    public int getLastIterationCount() {
        return lastIterationCount;
    }

    /**
     * The x component of gravity.
     *
     * @return gx (px/s²)
     */
    public float getGravityX() {
        return gravityX;
    }

    /**
     * The y component of gravity (positive pulls down the screen).
     *
     * @return gy (px/s²)
     */
    public float getGravityY() {
        return gravityY;
    }

    /**
     * Sets gravity, in any direction, including zero (a top-down world).
     *
     * @param gx x component (px/s²)
     * @param gy y component (px/s²)
     */
    public void setGravity(float gx, float gy) {
        gravityX = Check.finite("World.setGravity", "gx", gx);
        gravityY = Check.finite("World.setGravity", "gy", gy);
    }

    /**
     * The fraction of linear velocity removed each tick.
     *
     * @return the damping, in [0, 1]
     */
    public float getDampingLateral() {
        return dampingLateral;
    }

    /**
     * Sets the fraction of linear velocity removed each tick (the manual suggests 0 to 0.05).
     *
     * @param damping the fraction, in [0, 1]
     */
    public void setDampingLateral(float damping) {
        dampingLateral = Check.unit("World.setDampingLateral", "damping", damping);
    }

    /**
     * The fraction of angular velocity removed each tick.
     *
     * @return the damping, in [0, 1]
     */
    public float getDampingRotational() {
        return dampingRotational;
    }

    /**
     * Sets the fraction of angular velocity removed each tick.
     *
     * @param damping the fraction, in [0, 1]
     */
    public void setDampingRotational(float damping) {
        dampingRotational = Check.unit("World.setDampingRotational", "damping", damping);
    }

    /**
     * The contact solver's tuning, to read or change between ticks.
     *
     * @return the settings object of this world
     */
    public SolverSettings getSolverSettings() {
        return settings;
    }

    // ---------------------------------------------------------------------------------------------
    // Bodies

    /**
     * Adds a body. A body belongs to one world at a time.
     *
     * @param body the body
     */
    public void addBody(Body body) {
        Check.notNull("World.addBody", "body", body);
        if (body.world != null) {
            throw new IllegalArgumentException("World.addBody: " + body + " already belongs to a world");
        }
        int slot = freeSlotCount > 0 ? freeSlots[--freeSlotCount] : slotHigh++;
        if (slot == slots.length) {
            Body[] grown = new Body[slots.length * 2];
            System.arraycopy(slots, 0, grown, 0, slots.length);
            slots = grown;
        }
        slots[slot] = body;
        if (bodyCount == bodies.length) {
            Body[] grown = new Body[bodies.length * 2];
            System.arraycopy(bodies, 0, grown, 0, bodyCount);
            bodies = grown;
        }
        body.world = this;
        body.forceTick = tickCount;
        body.awake = false;
        body.solverIndex = 0;
        body.proxyDirty = false;
        ContactManager.forgetLandscape(body);
        body.id = nextBodyId++;
        body.worldIndex = bodyCount;
        bodies[bodyCount++] = body;
        body.slot = slot;
        body.getShape().computeAabb(body.x, body.y, body.c, body.s, aabb);
        body.proxyId = broadPhase.createProxy(aabb[0], aabb[1], aabb[2], aabb[3], slot, !body.isDynamic());
    }

    /**
     * Removes a body, its contacts and the constraints that act on it. Other bodies keep their
     * order.
     *
     * @param body the body
     * @return true when the body was in this world
     */
    public boolean removeBody(Body body) {
        if (body == null || body.world != this) {
            return false;
        }
        contacts.destroyContactsOf(body);
        removeConstraintsOf(body);
        particles.removeEmittersOf(body);
        broadPhase.destroyProxy(body.proxyId);
        slots[body.slot] = null;
        if (freeSlotCount == freeSlots.length) {
            int[] grown = new int[freeSlotCount * 2];
            System.arraycopy(freeSlots, 0, grown, 0, freeSlotCount);
            freeSlots = grown;
        }
        freeSlots[freeSlotCount++] = body.slot;
        int i = body.worldIndex;
        System.arraycopy(bodies, i + 1, bodies, i, bodyCount - i - 1);
        bodies[--bodyCount] = null;
        for (int k = i; k < bodyCount; k++) {
            bodies[k].worldIndex = k;
        }
        body.world = null;
        body.worldIndex = -1;
        body.proxyId = -1;
        body.slot = -1;
        body.awake = false;
        body.solverIndex = 0;
        body.proxyDirty = false;
        return true;
    }

    /**
     * The number of bodies.
     *
     * @return the count
     */
    public int getBodyCount() {
        return bodyCount;
    }

    /**
     * A body by its position in the world's list (insertion order).
     *
     * @param index 0 to {@link #getBodyCount()} − 1
     * @return the body
     */
    public Body getBody(int index) {
        if (index < 0 || index >= bodyCount) {
            throw new IndexOutOfBoundsException("World.getBody: index " + index + " of " + bodyCount);
        }
        return bodies[index];
    }

    /**
     * Finds a body by the id the world gave it.
     *
     * @param id the id
     * @return the body, or null
     */
    public Body findBodyById(int id) {
        for (int i = 0; i < bodyCount; i++) {
            if (bodies[i].id == id) {
                return bodies[i];
            }
        }
        return null;
    }

    Body bodyInSlot(int slot) {
        return slots[slot];
    }

    int getBroadPhaseUserData(int proxyId) {
        return broadPhase.getUserData(proxyId);
    }

    void bodyGeometryChanged(Body b) {
        if (!b.proxyDirty) {
            b.proxyDirty = true;
            if (dirtyCount == dirtyBodies.length) {
                Body[] grown = new Body[2 * dirtyCount];
                System.arraycopy(dirtyBodies, 0, grown, 0, dirtyCount);
                dirtyBodies = grown;
            }
            dirtyBodies[dirtyCount++] = b;
        }
    }

    void bodyShapeChanged(Body b) {
        // Contacts name the shape's parts: start afresh.
        contacts.destroyContactsOf(b);
        bodyGeometryChanged(b);
        broadPhase.touchProxy(b.proxyId);
        ContactManager.forgetLandscape(b);
    }

    void bodyFilterChanged(Body b) {
        contacts.markFilterDirty(b);
        broadPhase.setStatic(b.proxyId, !b.isDynamic());
        broadPhase.touchProxy(b.proxyId);
        ContactManager.forgetLandscape(b);
    }

    // ---------------------------------------------------------------------------------------------
    // Landscape and simulation area

    /**
     * The world's landscape. A new world has an empty one.
     *
     * @return the landscape, never null
     */
    public Landscape getLandscape() {
        return landscape;
    }

    /**
     * Replaces the world's landscape; contacts with the old one end at the next tick.
     *
     * @param landscape the landscape
     */
    public void setLandscape(Landscape landscape) {
        this.landscape = Check.notNull("World.setLandscape", "landscape", landscape);
    }

    /**
     * Restricts the simulation to a rectangle. A dynamic body counts as inside when its bounding
     * box overlaps the rectangle; bodies outside are frozen and cost nothing: they are not
     * integrated, not moved in the broadphase, not collided with each other or the landscape and
     * not solved. Bodies inside still collide with frozen bodies, which stand still like static
     * ones, so nothing falls into a body beyond the edge. A frozen body keeps its velocity and
     * moves on when the area, which may be moved between any two ticks, takes it in again.
     * Constraints between a body inside and a frozen one hold the frozen one fixed.
     *
     * @param minX the left edge (px)
     * @param minY the top edge (px)
     * @param maxX the right edge (px), ≥ minX
     * @param maxY the bottom edge (px), ≥ minY
     */
    public void setSimulationArea(float minX, float minY, float maxX, float maxY) {
        checkRectangle("World.setSimulationArea", "area", minX, minY, maxX, maxY);
        area.set(minX, minY, maxX, maxY);
    }

    /**
     * Restricts the simulation to a range of x over the full height, like the original engine's
     * {@code setSimulationArea(start, end)}; see {@link #setSimulationArea(float, float, float, float)}.
     *
     * @param startX the left edge (px)
     * @param endX the right edge (px), ≥ startX
     */
    public void setSimulationArea(float startX, float endX) {
        setSimulationArea(startX, -Float.MAX_VALUE, endX, Float.MAX_VALUE);
    }

    /** Simulates the whole world again (the default). */
    public void clearSimulationArea() {
        area.clear();
    }

    /**
     * Whether a simulation area is set.
     *
     * @return true when the simulation is restricted to an area
     */
    public boolean hasSimulationArea() {
        return area.isBounded();
    }

    /**
     * The left edge of the simulation area.
     *
     * @return min x (px); meaningless without an area
     */
    public float getSimulationAreaMinX() {
        return area.minX();
    }

    /**
     * The top edge of the simulation area.
     *
     * @return min y (px); meaningless without an area
     */
    public float getSimulationAreaMinY() {
        return area.minY();
    }

    /**
     * The right edge of the simulation area.
     *
     * @return max x (px); meaningless without an area
     */
    public float getSimulationAreaMaxX() {
        return area.maxX();
    }

    /**
     * The bottom edge of the simulation area.
     *
     * @return max y (px); meaningless without an area
     */
    public float getSimulationAreaMaxY() {
        return area.maxY();
    }

    /**
     * The number of dynamic bodies the last tick simulated: all of them without a simulation area,
     * those inside it with one.
     *
     * @return the count
     */
    public int getSimulatedBodyCount() {
        return area.count;
    }

    /**
     * A body the last tick simulated (see {@link Body#isSimulated()}), in world order.
     *
     * @param index 0 to {@link #getSimulatedBodyCount()} − 1
     * @return the body
     */
    public Body getSimulatedBody(int index) {
        if (index < 0 || index >= area.count) {
            throw new IndexOutOfBoundsException("World.getSimulatedBody: index " + index + " of " + area.count);
        }
        return area.bodies[index];
    }

    /**
     * Reports, by their index in the world's list ({@link #getBody(int)}), the bodies whose bounding
     * box, where they are now, overlaps a rectangle (touching counts), each once, in increasing
     * index order, until the callback returns false. The cost follows the last tick's simulated
     * bodies and the bodies found: static and frozen bodies elsewhere cost nothing, as they are
     * found through the broadphase.
     *
     * @param minX the left edge (px)
     * @param minY the top edge (px)
     * @param maxX the right edge (px), ≥ minX
     * @param maxY the bottom edge (px), ≥ minY
     * @param callback receives the indices; it must not add or remove bodies
     */
    public void queryBodies(float minX, float minY, float maxX, float maxY, QueryCallback callback) {
        checkRectangle("World.queryBodies", "rectangle", minX, minY, maxX, maxY);
        Check.notNull("World.queryBodies", "callback", callback);
        bodyQuery.run(this, broadPhase, area, dirtyBodies, dirtyCount, minX, minY, maxX, maxY, callback);
    }

    private static void checkRectangle(String where, String what, float minX, float minY, float maxX, float maxY) {
        Check.finite(where, "minX", minX);
        Check.finite(where, "minY", minY);
        Check.finite(where, "maxX", maxX);
        Check.finite(where, "maxY", maxY);
        if (maxX < minX || maxY < minY) {
            throw new IllegalArgumentException(where + ": the " + what + " (" + minX + ", " + minY + ") to (" + maxX
                + ", " + maxY + ") has max < min");
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Constraints

    /**
     * Adds a constraint (a joint, spring, motor or one of the application's own). Constraints are
     * solved in the order they were added, before the contacts.
     *
     * @param constraint the constraint
     */
    public void addConstraint(Constraint constraint) {
        Check.notNull("World.addConstraint", "constraint", constraint);
        for (int i = 0; i < constraintCount; i++) {
            if (constraints[i] == constraint) {
                throw new IllegalArgumentException("World.addConstraint: the constraint is already in this world");
            }
        }
        if (constraintCount == constraints.length) {
            Constraint[] grown = new Constraint[constraintCount * 2];
            System.arraycopy(constraints, 0, grown, 0, constraintCount);
            constraints = grown;
        }
        constraints[constraintCount++] = constraint;
    }

    /**
     * Removes a constraint.
     *
     * @param constraint the constraint
     * @return true when it was in this world
     */
    public boolean removeConstraint(Constraint constraint) {
        for (int i = 0; i < constraintCount; i++) {
            if (constraints[i] == constraint) {
                System.arraycopy(constraints, i + 1, constraints, i, constraintCount - i - 1);
                constraints[--constraintCount] = null;
                return true;
            }
        }
        return false;
    }

    /**
     * The number of constraints.
     *
     * @return the count
     */
    public int getConstraintCount() {
        return constraintCount;
    }

    /**
     * A constraint by its position in the world's list (insertion order).
     *
     * @param index 0 to {@link #getConstraintCount()} − 1
     * @return the constraint
     */
    public Constraint getConstraint(int index) {
        if (index < 0 || index >= constraintCount) {
            throw new IndexOutOfBoundsException("World.getConstraint: index " + index + " of " + constraintCount);
        }
        return constraints[index];
    }

    private void removeConstraintsOf(Body body) {
        int kept = 0;
        for (int i = 0; i < constraintCount; i++) {
            if (!constraints[i].concernsBody(body)) {
                constraints[kept++] = constraints[i];
            }
        }
        for (int i = kept; i < constraintCount; i++) {
            constraints[i] = null;
        }
        constraintCount = kept;
    }

    // ---------------------------------------------------------------------------------------------
    // External forces

    /**
     * Adds an external force, applied at the start of every tick before anything moves.
     *
     * @param force the force
     */
    public void addExternalForce(ExternalForce force) {
        Check.notNull("World.addExternalForce", "force", force);
        if (indexOf(forces, forceCount, force) >= 0) {
            throw new IllegalArgumentException("World.addExternalForce: the force is already in this world");
        }
        forces = grown(forces, forceCount);
        forces[forceCount++] = force;
    }

    /**
     * Removes an external force.
     *
     * @param force the force
     * @return true when it was in this world
     */
    public boolean removeExternalForce(ExternalForce force) {
        int i = indexOf(forces, forceCount, force);
        if (i < 0) {
            return false;
        }
        forceCount = removeAt(forces, forceCount, i);
        return true;
    }

    /**
     * The number of external forces.
     *
     * @return the count
     */
    public int getExternalForceCount() {
        return forceCount;
    }

    /**
     * An external force by its position in the world's list (insertion order).
     *
     * @param index 0 to {@link #getExternalForceCount()} − 1
     * @return the force
     */
    public ExternalForce getExternalForce(int index) {
        if (index < 0 || index >= forceCount) {
            throw new IndexOutOfBoundsException("World.getExternalForce: index " + index + " of " + forceCount);
        }
        return forces[index];
    }

    // ---------------------------------------------------------------------------------------------
    // Events

    /**
     * Sets the listener that is told about events. Events are checked at the end of every tick,
     * in the order they were added, only while a listener is set: without one they cost nothing.
     *
     * @param listener the listener, or null to stop checking events
     */
    public void setPhysicsEventListener(PhysicsEventListener listener) {
        eventListener = listener;
    }

    /**
     * The listener told about events.
     *
     * @return the listener, or null
     */
    public PhysicsEventListener getPhysicsEventListener() {
        return eventListener;
    }

    /**
     * Adds an event to check at the end of every tick.
     *
     * @param event the event
     */
    public void addEvent(Event event) {
        Check.notNull("World.addEvent", "event", event);
        if (indexOf(events, eventCount, event) >= 0) {
            throw new IllegalArgumentException("World.addEvent: the event is already in this world");
        }
        events = grown(events, eventCount);
        events[eventCount++] = event;
    }

    /**
     * Removes an event.
     *
     * @param event the event
     * @return true when it was in this world
     */
    public boolean removeEvent(Event event) {
        int i = indexOf(events, eventCount, event);
        if (i < 0) {
            return false;
        }
        eventCount = removeAt(events, eventCount, i);
        return true;
    }

    /**
     * The number of events.
     *
     * @return the count
     */
    public int getEventCount() {
        return eventCount;
    }

    /**
     * An event by its position in the world's list (insertion order); the position is the
     * original engine's event id.
     *
     * @param index 0 to {@link #getEventCount()} − 1
     * @return the event
     */
    public Event getEvent(int index) {
        if (index < 0 || index >= eventCount) {
            throw new IndexOutOfBoundsException("World.getEvent: index " + index + " of " + eventCount);
        }
        return events[index];
    }

    private static int indexOf(Object[] list, int count, Object item) {
        for (int i = 0; i < count; i++) {
            if (list[i] == item) {
                return i;
            }
        }
        return -1;
    }

    /** The list itself, or a copy twice as long when it is full. */
    private static <T> T[] grown(T[] list, int count) {
        return count < list.length ? list : java.util.Arrays.copyOf(list, count * 2);
    }

    /** Removes an element keeping the order; returns the new count. */
    private static int removeAt(Object[] list, int count, int i) {
        System.arraycopy(list, i + 1, list, i, count - i - 1);
        list[count - 1] = null;
        return count - 1;
    }

    // ---------------------------------------------------------------------------------------------
    // Particle emitters

    /**
     * Adds a particle emitter; its particles move at the end of every tick, after the bodies.
     *
     * @param emitter the emitter, in no other world; its body, if any, must be in this world
     */
    public void addParticleEmitter(ParticleEmitter emitter) {
        Check.notNull("World.addParticleEmitter", "emitter", emitter);
        Body b = emitter.getBody();
        if (b != null && b.world != this) {
            throw new IllegalArgumentException("World.addParticleEmitter: the emitter's body " + b + " is not in this world");
        }
        if (!particles.addEmitter(emitter)) {
            throw new IllegalArgumentException("World.addParticleEmitter: " + emitter + " already belongs to a world");
        }
    }

    /**
     * Removes a particle emitter (removing its body does this too).
     *
     * @param emitter the emitter
     * @return true when it was in this world
     */
    public boolean removeParticleEmitter(ParticleEmitter emitter) {
        return particles.removeEmitter(emitter);
    }

    /**
     * The number of particle emitters.
     *
     * @return the count
     */
    public int getParticleEmitterCount() {
        return particles.getEmitterCount();
    }

    /**
     * A particle emitter by its position in the world's list (insertion order).
     *
     * @param index 0 to {@link #getParticleEmitterCount()} − 1
     * @return the emitter
     */
    public ParticleEmitter getParticleEmitter(int index) {
        if (index < 0 || index >= particles.getEmitterCount()) {
            throw new IndexOutOfBoundsException("World.getParticleEmitter: index " + index + " of " + particles.getEmitterCount());
        }
        return particles.getEmitter(index);
    }

    // ---------------------------------------------------------------------------------------------
    // Contacts

    /**
     * The number of contacts, touching or not: pairs of bodies close enough to be tested (one per
     * pair of parts for multi-shapes) and bodies near landscape segments (one per segment).
     *
     * @return the count
     */
    public int getContactCount() {
        return contacts.count;
    }

    /**
     * A contact by index. Valid until the next tick.
     *
     * @param index 0 to {@link #getContactCount()} − 1
     * @return the contact
     */
    public Contact getContact(int index) {
        if (index < 0 || index >= contacts.count) {
            throw new IndexOutOfBoundsException("World.getContact: index " + index + " of " + contacts.count);
        }
        return contacts.contacts[index];
    }

    /**
     * Whether the last tick left pairs of bodies (or a body and a landscape segment) whose boxes
     * met without contacts, because the world held {@link SolverSettings#getMaxContacts()}
     * contacts: those bodies pass through each other until contacts end and make room.
     *
     * @return true when the contact capacity was reached
     */
    public boolean isContactCapacityReached() {
        return contacts.capacityReached;
    }

    /**
     * The number of ticks run so far.
     *
     * @return the tick count
     */
    public long getTickCount() {
        return tickCount;
    }

    // ---------------------------------------------------------------------------------------------
    // The tick

    /**
     * Advances the world by one timestep: external forces, collision detection, the solve (constraints
     * and contacts), then, when a listener is set, the events.
     */
    public void tick() {
        float dt = timestep;
        for (int i = 0; i < forceCount; i++) {
            forces[i].applyForce(this, dt);
        }
        area.collect(this, broadPhase, bodies, bodyCount);
        contacts.beginLandscape(landscape);
        updateBroadPhase(dt);
        contacts.updatePairs(broadPhase);
        if (area.isBounded()) {
            contacts.gather(area.bodies, area.count, tickCount);
        } else {
            contacts.gatherAll();
        }
        contacts.collide(broadPhase, dt, settings.getSpeculativeDistance());
        solve(dt);
        if (particles.getEmitterCount() > 0) {
            particles.step(this, dt);
        }
        tickCount++;
        if (eventListener != null) {
            for (int i = 0; i < eventCount; i++) {
                events[i].check(this, eventListener);
            }
        }
    }

    /** Moves the proxies of the simulated bodies and of the bodies the application moved. */
    private void updateBroadPhase(float dt) {
        // A changed SolverSettings.setAabbMargin re-fattens every box (nothing when unchanged).
        broadPhase.setMargin(settings.getAabbMargin());
        float[] box = aabb;
        for (int i = 0; i < dirtyCount; i++) {
            Body b = dirtyBodies[i];
            dirtyBodies[i] = null;
            if (b.world != this || !b.proxyDirty || b.awake) {
                continue;
            }
            b.proxyDirty = false;
            b.getShape().computeAabb(b.x, b.y, b.c, b.s, box);
            broadPhase.moveProxy(b.proxyId, box[0], box[1], box[2], box[3], 0f, 0f);
            ContactManager.forgetLandscape(b);
        }
        dirtyCount = 0;
        Body[] simulated = area.bodies;
        for (int i = 0, n = area.count; i < n; i++) {
            Body b = simulated[i];
            b.proxyDirty = false;
            b.getShape().computeAabb(b.x, b.y, b.c, b.s, box);
            boolean moved = broadPhase.moveProxy(b.proxyId, box[0], box[1], box[2], box[3], b.vx * dt, b.vy * dt);
            contacts.findLandscapeContacts(b, moved, broadPhase);
        }
    }

    private void solve(float dt) {
        int n = iterations;
        float h = dt / n;
        SolverBodies sb = solverBodies;
        Body[] simulated = area.bodies;
        int simulatedCount = area.count;
        sb.reset(simulatedCount);
        for (int i = 0; i < simulatedCount; i++) {
            Body b = simulated[i];
            b.solverIndex = sb.add(b, gravityX, gravityY, tickCount);
        }
        setSoftness(h);
        float jointHertz = settings.getJointHertz();
        float jointDamping = settings.getJointDampingRatio();
        step.begin(dt, h, jointHertz, jointDamping);
        contactSolver.prepare(contacts.active, contacts.activeCount, sb, soft, staticSoft);
        // Stored impulses belong to the substep they were computed for.
        if (lastSubstep != 0f && lastSubstep != h) {
            contactSolver.scaleImpulses(h / lastSubstep);
        }
        Constraint[] cs = constraints;
        int cn = constraintCount;
        for (int c = 0; c < cn; c++) {
            cs[c].prepare(step);
        }
        float maxPush = settings.getContactPushMaxVelocity();
        float slop = settings.getLinearSlop();
        float tolerance = settings.getConvergenceTolerance();
        float impactTolerance = settings.getImpactTolerance();
        int impactPasses = settings.getImpactRelaxPasses();
        int used = 0;
        float hh = h;
        float change = Float.MAX_VALUE;
        boolean converged = false;
        for (int i = 0; i < n; i++) {
            float invH = 1f / hh;
            sb.integrateVelocities(hh);
            for (int c = 0; c < cn; c++) {
                cs[c].warmStart(step);
            }
            contactSolver.warmStart(sb);
            if (!converged) {
                for (int c = 0; c < cn; c++) {
                    cs[c].solve(step, true);
                }
                contactSolver.solve(sb, true, invH, maxPush, slop, false);
            }
            sb.integratePositions(hh);
            if (!converged) {
                change = 0f;
                for (int c = 0; c < cn; c++) {
                    change = Math.max(change, cs[c].solve(step, false));
                }
                contactSolver.relax(sb, invH, maxPush, slop, dynamicIterations, impactTolerance);
                contactSolver.relaxHot(sb, invH, maxPush, slop, impactTolerance, impactPasses);
                change = Math.max(change, contactSolver.lastRelaxChange);
                used++;
                converged = dynamicIterations && change < tolerance;
            }
        }
        contactSolver.applyRestitution(sb, settings.getRestitutionThreshold());
        contactSolver.storeImpulses();
        for (int c = 0; c < cn; c++) {
            cs[c].finish(step);
        }
        continuous.solve(sb, broadPhase, 4f * slop + 0.05f);
        lastSubstep = hh;
        lastIterationCount = used;
        Body bad = sb.writeBack(1f - dampingLateral, 1f - dampingRotational);
        if (bad != null) {
            throw new IllegalStateException("World.tick: " + bad + " became non-finite in tick " + tickCount
                + "; check the forces and settings applied to it");
        }
    }

    private void setSoftness(float h) {
        float hertz = Math.min(settings.getContactHertz(), 0.25f / h);
        soft.set(hertz, settings.getContactDampingRatio(), h);
        staticSoft.set(2f * hertz, settings.getContactDampingRatio(), h);
    }
}
