package org.emini.dynamics;

import java.util.concurrent.ThreadFactory;
import org.emini.collision.BroadPhase;
import org.emini.collision.QueryCallback;
import org.emini.internal.ChangeQueue;
import org.emini.internal.Check;
import org.emini.internal.ElementList;
import org.emini.internal.WorkerPool;
import org.emini.math.EMath;
import org.emini.shape.Shape;

/**
 * The physics of a world: bodies, constraints, contacts, the landscape, the simulation area, and
 * the solve. {@code org.emini.world.World} is the class applications use: it adds what acts before
 * the solve (external forces) and what reads its result (particles, events) on top of this one, so
 * the packages read as a pipeline (dynamics below constraint, event and particle, the world above).
 *
 * <p>Defaults are the original engine's: 20 ticks per second, 10 iterations, gravity (0, 100) px/s²
 * pointing down the screen, no damping.
 *
 * <p>One tick: find the bodies to simulate (all dynamic bodies, or those inside the
 * {@linkplain #setSimulationArea(float, float, float, float) simulation area}); update the
 * broadphase and create contacts for pairs that came close and for bodies near segments of the
 * {@link Landscape}; run the narrowphase on the simulated bodies' contacts; then solve. The solver
 * splits the tick into substeps, one per iteration (more in a tick where a heavy body would sink
 * into a light one deeper than {@link SolverSettings#getSinkLimit()}): each substep integrates velocities, bounces the
 * elastic impacts that close within it (pairwise collisions), warm-starts, makes one soft
 * (position-correcting) pass over the contacts, integrates positions and makes one rigid relax pass.
 * In dynamic-iteration mode the solver stops solving once a substep's impulses differ from those it
 * started with by no more than {@link SolverSettings#getConvergenceTolerance()} (as velocity) and
 * no speculative gap can close before the tick ends: the remaining substeps only integrate,
 * re-applying the converged impulses (warm start) so resting stacks stay put.
 *
 * <p>Changing the world while it ticks (from an external force, a {@link Constraint} or an event
 * listener): adding and removing bodies, constraints and the world's other elements, and replacing
 * the landscape, are applied in the order made when the tick ends, so the lists stay as they were
 * while the tick walks them ({@code remove...} answers whether the element will be gone).
 * {@link #tick()} is not re-entrant. While the solver holds its copies of the bodies (a
 * constraint's callbacks), velocities, impulses and forces set on a body reach the copy and act in
 * this tick, as the manual's jump in a motor's prepare does; changing a body's pose, shape or kind
 * there is refused with an {@link IllegalStateException}, and a body's getters give its state as the
 * tick began (read the current one through the {@link SolverStep}).
 *
 * <p>A tick allocates nothing once the world's arrays have grown to the scene, and the same world
 * with the same inputs gives bit-identical results.
 */
public abstract class Simulation {
    private float timestep = 1f / 20f;
    private int iterations = 10;
    private boolean dynamicIterations;
    // Inside tick(): structural changes wait here.
    private final ChangeQueue changes = new ChangeQueue();
    private final ChangeQueue.Target bodyChanges = new ChangeQueue.Target() {
        @Override
        public void apply(Object item, boolean add) {
            if (add) {
                addBody((Body) item);
            } else {
                removeBody((Body) item);
            }
        }
    };
    private final ChangeQueue.Target landscapeChange = new ChangeQueue.Target() {
        @Override
        public void apply(Object item, boolean add) {
            setLandscape((Landscape) item);
        }
    };
    private final ChangeQueue.Target shapeChange = new ChangeQueue.Target() {
        @Override
        public void apply(Object item, boolean add) {
            Body b = (Body) item;
            if (b.world == Simulation.this) {
                bodyShapeChanged(b);
            }
        }
    };
    private float gravityX;
    private float gravityY = 100f;
    private float dampingLateral;
    private float dampingRotational;
    private CollisionFilter collisionFilter;
    private final SolverSettings settings = new SolverSettings();

    private final BodyTable bodies = new BodyTable();

    private final BroadPhase broadPhase;
    final ProxySync proxies;
    // What each broadphase proxy stands for: a body's part.
    private final PartKeys partKeys = new PartKeys();
    private final ContactManager contacts = new ContactManager(this, partKeys);
    final Solver solver = new Solver(this);
    /** The most threads {@link #setWorkerCount} takes. */
    public static final int MAX_WORKERS = 64;
    /**
     * The fewest simulated bodies for which a tick shares its loops with the worker threads. Below it
     * the hand-offs cost more than they save. Separate JVMs, 3 runs each (median, range), 2026-11-29: the
     * 20-row pyramid (211 bodies) took 0.254 ms a tick at two threads (0.240-0.265) against 0.239 at one
     * (0.230-0.290), rain of 200 bodies 0.248 (0.236-0.248) against 0.226 (0.225-0.277), while rain of
     * 500 took 0.572 (0.553-0.576) against 0.663 (0.657-0.680).
     */
    static final int MIN_THREADED_BODIES = 400;
    private WorkerPool pool;
    /** Ticks with fewer simulated bodies than this run on the calling thread alone (see setWorkerCount). */
    private int minThreadedBodies = MIN_THREADED_BODIES;
    private final ElementList<Constraint> constraints = new ElementList<Constraint>(changes, new Constraint[8], "Constraint",
        "constraint");
    private Landscape landscape = new Landscape();
    private final SimulationArea area = new SimulationArea();
    private final BodyQuery bodyQuery = new BodyQuery();
    private final WorldQuery worldQuery = new WorldQuery(this);
    final StepData stepData = new StepData();
    private PreSolveListener preSolve;
    private final SensorSet sensors = new SensorSet();
    final Sleep sleep = new Sleep();
    private float hitEventThreshold = Float.POSITIVE_INFINITY;
    private long tickCount;

    /** Creates an empty world with the original engine's defaults. */
    protected Simulation() {
        broadPhase = new BroadPhase(settings.getAabbMargin());
        proxies = new ProxySync(this, broadPhase, contacts, partKeys);
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

    /** The shortest timestep (s): a million ticks a second; shorter ones make rates (1/h) overflow. */
    public static final float MIN_TIMESTEP = 1e-6f;

    /**
     * Sets the length of one tick.
     *
     * @param seconds the timestep (s), finite and at least {@link #MIN_TIMESTEP}
     */
    public void setTimestep(float seconds) {
        Check.positive("World.setTimestep", "seconds", seconds);
        if (seconds < MIN_TIMESTEP) {
            throw new IllegalArgumentException("World.setTimestep: seconds must be >= " + MIN_TIMESTEP + " (World.MIN_TIMESTEP),"
                + " was " + seconds);
        }
        timestep = seconds;
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
     * The solver's effort per tick: the number of substeps (each a soft solve and a relax pass), the
     * fewest the solver takes (see {@link SolverSettings#getSinkLimit()}).
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
     * The number of iterations (substeps) the last tick solved: in dynamic mode those before it
     * converged, and more than the iteration count where the sink limit asked for them.
     *
     * @return the count
     */
    public int getLastIterationCount() {
        return solver.getLastIterationCount();
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
        Check.finite("World.setGravity", "gx", gx);
        Check.finite("World.setGravity", "gy", gy);
        if (gx != gravityX || gy != gravityY) {
            gravityX = gx;
            gravityY = gy;
            sleep.wakeAll(this);
        }
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
     * Adds a body. A body belongs to one world at a time. During a tick (from an external force, a
     * constraint or an event listener) the body is added when the tick ends, as are all structural
     * changes made then.
     *
     * @param body the body
     */
    public void addBody(Body body) {
        Check.notNull("World.addBody", "body", body);
        if (body.world != null || (changes.isOpen() && changes.willContain(bodyChanges, body, false))) {
            throw new IllegalArgumentException("World.addBody: " + body + " already belongs to a world");
        }
        if (changes.isOpen()) {
            changes.add(bodyChanges, body, true);
            return;
        }
        bodies.add(body);
        body.world = this;
        body.forceTick = tickCount;
        body.awake = false;
        body.solverIndex = 0;
        proxies.create(body);
        if (body.sensor) {
            sensors.add(body);
        }
    }

    /**
     * Removes a body, its contacts and the constraints that act on it. Other bodies keep their
     * order. During a tick the body is removed when the tick ends.
     *
     * @param body the body
     * @return true when the body was in this world (during a tick: will be, when the tick ends)
     */
    public boolean removeBody(Body body) {
        if (changes.isOpen()) {
            boolean there = body != null && willContain(body);
            if (there) {
                changes.add(bodyChanges, body, false);
            }
            return there;
        }
        if (body == null || body.world != this) {
            return false;
        }
        sleep.wakeNeighbours(body);
        contacts.destroyContactsOf(body);
        removeConstraintsOf(body);
        if (body.sensor) {
            sensors.remove(body, stepData);
        }
        bodyRemoved(body);
        proxies.destroy(body);
        bodies.remove(body);
        body.world = null;
        body.awake = false;
        body.solverIndex = 0;
        return true;
    }

    /**
     * The number of bodies.
     *
     * @return the count
     */
    public int getBodyCount() {
        return bodies.count();
    }

    /**
     * A body by its position in the world's list (insertion order).
     *
     * @param index 0 to {@link #getBodyCount()} − 1
     * @return the body
     */
    public Body getBody(int index) {
        int count = bodies.count();
        if (index < 0 || index >= count) {
            throw new IndexOutOfBoundsException("World.getBody: index " + index + " of " + count);
        }
        return bodies.ordered()[index];
    }

    /**
     * Finds a body by the id the world gave it, in O(log n) time (ids grow in the order of the list).
     *
     * @param id the id
     * @return the body, or null
     */
    public Body findBodyById(int id) {
        return bodies.findById(id);
    }

    /** The broadphase proxy of a body's part. */
    int proxyOf(Body b, int part) {
        return partKeys.proxy(b.partKeys[part]);
    }

    /** The body a broadphase proxy stands for (one of its parts). */
    Body bodyOfProxy(int proxyId) {
        return partKeys.body(broadPhase.getUserData(proxyId));
    }

    /** A body became a sensor or solid again. */
    void sensorChanged(Body b) {
        if (b.sensor) {
            sensors.add(b);
        } else {
            sensors.remove(b, stepData);
        }
    }

    /** A new shape: during a tick its contacts still name the old shape's parts, so they end when it ends. */
    void bodyShapeChanged(Body b) {
        sleep.wake(b);
        if (changes.isOpen()) {
            changes.add(shapeChange, b, true);
            proxies.geometryChanged(b);
        } else {
            proxies.shapeChanged(b);
        }
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
     * Replaces the world's landscape; contacts with the old one end at the next tick. During a tick
     * the landscape is replaced when the tick ends.
     *
     * @param landscape the landscape
     */
    public void setLandscape(Landscape landscape) {
        Check.notNull("World.setLandscape", "landscape", landscape);
        if (changes.isOpen()) {
            changes.add(landscapeChange, landscape, true);
            return;
        }
        this.landscape = landscape;
    }

    /**
     * Restricts the simulation to a rectangle. A dynamic or kinematic body counts as inside when
     * its bounding box overlaps the rectangle; bodies outside are frozen and cost nothing: they are
     * not integrated, not moved in the broadphase, not collided with each other or the landscape and
     * not solved. Bodies inside still collide with frozen bodies, which stand still like static
     * ones, so nothing falls into a body beyond the edge. A frozen body keeps its velocity and
     * moves on when the area, which may be moved between any two ticks, takes it in again: a
     * kinematic platform that leaves the area stops just past its edge, as a dynamic body does, and
     * goes on when the area reaches it. Constraints between a body inside and a frozen one hold the
     * frozen one fixed.
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
     * The number of dynamic and kinematic bodies the last tick simulated: all of them without a
     * simulation area, those inside it with one.
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
        // Results come in world order, by index.
        bodies.closeHoles();
        bodyQuery.run(this, broadPhase, area, proxies.dirty, proxies.dirtyCount, minX, minY, maxX, maxY, callback);
    }

    /** Runs a body query (a box, or a box swept by (dx, dy)) over the world's bodies as they are now. */
    void findBodies(BodyQuery query, float minX, float minY, float maxX, float maxY, float dx, float dy,
            QueryCallback out) {
        bodies.closeHoles();
        query.runSwept(this, broadPhase, area, proxies.dirty, proxies.dirtyCount, minX, minY, maxX, maxY, dx, dy, out);
    }

    // ---------------------------------------------------------------------------------------------
    // Queries: rays, swept shapes, points and overlaps

    /**
     * Casts a ray from (x1, y1) to (x2, y2) and finds the first thing it hits: a body (any kind:
     * static, dynamic, frozen outside the simulation area; where it is now, also when moved since
     * the last tick) or a landscape segment. Shapes are solid and closed: a ray that starts inside
     * or on a body hits it at fraction 0, the point and normal then giving the shortest way out (the
     * nearest point of its surface; a filter can look through the body a ray starts from); a
     * tangent hits. A zero-length ray is a point test.
     * A landscape segment is hit from either side, a faced one only by rays that start on its
     * blocking side (as it stops only bodies there); a ray starting on a segment's line or running
     * along it does not hit it. Ties go to the body first in world order, bodies before segments.
     * Costs as {@link #queryBodies} does for the ray's box, and allocates nothing.
     *
     * @param x1 the ray's start x (px)
     * @param y1 the ray's start y (px)
     * @param x2 the ray's end x (px)
     * @param y2 the ray's end y (px)
     * @param filter which bodies and segments may be hit, or null for all
     * @param out receives the closest hit, or is cleared when there is none
     * @return whether something was hit
     * @throws IllegalArgumentException naming the call and value when a coordinate is NaN or
     *     infinite, the ray is longer than a float holds, or out is null
     * @throws IllegalStateException when called from the callback or filter of a running query
     */
    public boolean rayCastClosest(float x1, float y1, float x2, float y2, QueryFilter filter, CastHit out) {
        String where = "World.rayCastClosest";
        checkRay(where, x1, y1, x2, y2);
        Check.notNull(where, "out", out);
        worldQuery.enter(where);
        try {
            return worldQuery.rayCastClosest(x1, y1, x2, y2, filter, out);
        } finally {
            worldQuery.exit();
        }
    }

    /**
     * Casts a ray from (x1, y1) to (x2, y2) and reports every hit, as Box2D's ray casts do: each
     * part of a body's shape the ray enters (a multi-shape part by part) and each landscape segment
     * it crosses, at or before the ray's current end, bodies in world order, then segments in
     * index order (not sorted by distance). The callback steers the ray: 0 stops it, a fraction
     * clips it there, −1 ignores the hit, 1 goes on (see {@link CastCallback#reportHit}); returning
     * each hit's fraction leaves the closest as the last one reported. What counts as a hit is as
     * for {@link #rayCastClosest}. Allocates nothing.
     *
     * @param x1 the ray's start x (px)
     * @param y1 the ray's start y (px)
     * @param x2 the ray's end x (px)
     * @param y2 the ray's end y (px)
     * @param callback receives the hits; it must not add or remove bodies or start another query
     * @throws IllegalArgumentException naming the call and value when a coordinate is NaN or
     *     infinite, the ray is longer than a float holds, or the callback is null
     * @throws IllegalStateException when the callback returns NaN, or when called from the
     *     callback or filter of a running query
     */
    public void rayCast(float x1, float y1, float x2, float y2, CastCallback callback) {
        String where = "World.rayCast";
        checkRay(where, x1, y1, x2, y2);
        Check.notNull(where, "callback", callback);
        worldQuery.enter(where);
        try {
            worldQuery.rayCast(x1, y1, x2, y2, callback);
        } finally {
            worldQuery.exit();
        }
    }

    /**
     * Sweeps a shape, placed with its origin at (x, y) and turned by angle, along the translation
     * (dx, dy) without turning, and finds the first body or landscape segment it touches: exactly
     * (vertex against face, circles as rounded faces and corners, in closed form), not by boxes or
     * steps. The hit's fraction is how much of the translation the shape travels before it
     * touches, the point where it touches, the normal the surface's there, pointing from what was
     * hit to the shape. A shape that overlaps or touches something at the start hits it at fraction
     * 0, the normal then giving its shortest way out (start a hair away to slide along a surface);
     * a zero translation is thus an overlap test. A faced landscape segment stops the shape only
     * when its origin starts on the blocking side, as it stops bodies. Ties go to the body first in
     * world order, bodies before segments. Allocates nothing.
     *
     * @param shape the shape to sweep (any kind; it need not belong to a body)
     * @param x the x of its origin at the start (px)
     * @param y the y of its origin at the start (px)
     * @param angle its angle (rad)
     * @param dx the translation's x (px)
     * @param dy the translation's y (px)
     * @param filter which bodies and segments may be hit, or null for all
     * @param out receives the first hit, or is cleared when there is none
     * @return whether something was hit
     * @throws IllegalArgumentException naming the call and value when a number is NaN or infinite,
     *     or the shape or out is null
     * @throws IllegalStateException when called from the callback or filter of a running query
     */
    public boolean castShapeClosest(Shape shape, float x, float y, float angle, float dx, float dy, QueryFilter filter,
            CastHit out) {
        String where = "World.castShapeClosest";
        checkCast(where, shape, x, y, angle, dx, dy);
        Check.notNull(where, "out", out);
        worldQuery.enter(where);
        try {
            return worldQuery.castShapeClosest(shape, x, y, EMath.cos(angle), EMath.sin(angle), dx, dy, filter, out);
        } finally {
            worldQuery.exit();
        }
    }

    /**
     * Sweeps a shape along a translation (see {@link #castShapeClosest}) and reports, for each part
     * of each body and each landscape segment it would touch, the first contact with it, at or
     * before the cast's current end: bodies in world order, then segments in index order. The
     * callback steers the cast as for {@link #rayCast}. Allocates nothing.
     *
     * @param shape the shape to sweep
     * @param x the x of its origin at the start (px)
     * @param y the y of its origin at the start (px)
     * @param angle its angle (rad)
     * @param dx the translation's x (px)
     * @param dy the translation's y (px)
     * @param callback receives the hits; it must not add or remove bodies or start another query
     * @throws IllegalArgumentException naming the call and value when a number is NaN or infinite,
     *     or the shape or callback is null
     * @throws IllegalStateException when the callback returns NaN, or when called from the
     *     callback or filter of a running query
     */
    public void castShape(Shape shape, float x, float y, float angle, float dx, float dy, CastCallback callback) {
        String where = "World.castShape";
        checkCast(where, shape, x, y, angle, dx, dy);
        Check.notNull(where, "callback", callback);
        worldQuery.enter(where);
        try {
            worldQuery.castShape(shape, x, y, EMath.cos(angle), EMath.sin(angle), dx, dy, callback);
        } finally {
            worldQuery.exit();
        }
    }

    /**
     * Reports, by their index in the world's list, the bodies whose shape contains a point (on the
     * boundary counts), in increasing index order, until the callback returns false. Bodies of
     * every kind are found where they are now, as by {@link #queryBodies}. Allocates nothing.
     *
     * @param x the point's x (px)
     * @param y the point's y (px)
     * @param callback receives the indices; it must not add or remove bodies or start another
     *     query
     * @throws IllegalArgumentException naming the call and value when a coordinate is NaN or
     *     infinite, or the callback is null
     * @throws IllegalStateException when called from the callback or filter of a running query
     */
    public void queryPoint(float x, float y, QueryCallback callback) {
        String where = "World.queryPoint";
        Check.finite(where, "x", x);
        Check.finite(where, "y", y);
        Check.notNull(where, "callback", callback);
        worldQuery.enter(where);
        try {
            worldQuery.queryPoint(x, y, callback);
        } finally {
            worldQuery.exit();
        }
    }

    /**
     * The body at a point, as the original engine's {@code findBodyAt}: the first body in world
     * order whose shape contains the point (on the boundary counts). Use {@link #queryPoint} for
     * all of them (the last one is the one drawn on top when bodies are drawn in world order).
     *
     * @param x the point's x (px)
     * @param y the point's y (px)
     * @return the body, or null when no body contains the point
     * @throws IllegalArgumentException naming the call and value when a coordinate is NaN or
     *     infinite
     * @throws IllegalStateException when called from the callback or filter of a running query
     */
    public Body findBodyAt(float x, float y) {
        String where = "World.findBodyAt";
        Check.finite(where, "x", x);
        Check.finite(where, "y", y);
        worldQuery.enter(where);
        try {
            return worldQuery.queryPoint(x, y, null);
        } finally {
            worldQuery.exit();
        }
    }

    /**
     * Reports, by their index in the world's list, the bodies whose shape overlaps a shape placed
     * with its origin at (x, y) and turned by angle: exactly (separating axes over the faces of
     * both and, for circles, the axis to the nearest corner), not by boxes; touching counts;
     * multi-shapes part by part. Bodies of every kind, where they are now, in increasing index
     * order, until the callback returns false. Allocates nothing.
     *
     * @param shape the shape (any kind; it need not belong to a body)
     * @param x the x of its origin (px)
     * @param y the y of its origin (px)
     * @param angle its angle (rad)
     * @param callback receives the indices; it must not add or remove bodies or start another
     *     query
     * @throws IllegalArgumentException naming the call and value when a number is NaN or infinite,
     *     or the shape or callback is null
     * @throws IllegalStateException when called from the callback or filter of a running query
     */
    public void overlapShape(Shape shape, float x, float y, float angle, QueryCallback callback) {
        String where = "World.overlapShape";
        checkCast(where, shape, x, y, angle, 0f, 0f);
        Check.notNull(where, "callback", callback);
        worldQuery.enter(where);
        try {
            worldQuery.overlapShape(shape, x, y, EMath.cos(angle), EMath.sin(angle), callback);
        } finally {
            worldQuery.exit();
        }
    }

    /**
     * Reports, by their index in the world's {@link Landscape}, the segments that a placed shape
     * overlaps or touches, exactly and whatever their facing, in increasing index order, until the
     * callback returns false. Allocates nothing.
     *
     * @param shape the shape
     * @param x the x of its origin (px)
     * @param y the y of its origin (px)
     * @param angle its angle (rad)
     * @param callback receives the segment indices; it must not change the landscape or start
     *     another query
     * @throws IllegalArgumentException naming the call and value when a number is NaN or infinite,
     *     or the shape or callback is null
     * @throws IllegalStateException when called from the callback or filter of a running query
     */
    public void overlapLandscape(Shape shape, float x, float y, float angle, QueryCallback callback) {
        String where = "World.overlapLandscape";
        checkCast(where, shape, x, y, angle, 0f, 0f);
        Check.notNull(where, "callback", callback);
        worldQuery.enter(where);
        try {
            worldQuery.overlapLandscape(shape, x, y, EMath.cos(angle), EMath.sin(angle), callback);
        } finally {
            worldQuery.exit();
        }
    }

    private static void checkRay(String where, float x1, float y1, float x2, float y2) {
        Check.finite(where, "x1", x1);
        Check.finite(where, "y1", y1);
        Check.finite(where, "x2", x2);
        Check.finite(where, "y2", y2);
        if (!EMath.isFinite(x2 - x1) || !EMath.isFinite(y2 - y1)) {
            throw new IllegalArgumentException(where + ": the ray from (" + x1 + ", " + y1 + ") to (" + x2 + ", " + y2
                + ") is longer than a float holds");
        }
    }

    private static void checkCast(String where, Shape shape, float x, float y, float angle, float dx, float dy) {
        Check.notNull(where, "shape", shape);
        Check.finite(where, "x", x);
        Check.finite(where, "y", y);
        Check.finite(where, "angle", angle);
        Check.finite(where, "dx", dx);
        Check.finite(where, "dy", dy);
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

    /**
     * Keeps two bodies from colliding with each other, whatever their layers (Box2D's
     * "collide connected" off for a joint: the bodies a joint holds together often overlap). Unlike a
     * shared collision layer bit, it affects no other pair. Takes effect at the next tick.
     *
     * @param a a body
     * @param b another body
     */
    public void disableCollision(Body a, Body b) {
        Check.notNull("World.disableCollision", "a", a);
        Check.notNull("World.disableCollision", "b", b);
        if (a == b) {
            throw new IllegalArgumentException("World.disableCollision: a and b are the same body, " + a);
        }
        a.exclude(b);
        b.exclude(a);
        collisionFilterChanged(a, b);
    }

    /**
     * Lets two bodies collide again after {@link #disableCollision}.
     *
     * @param a a body
     * @param b another body
     */
    public void enableCollision(Body a, Body b) {
        Check.notNull("World.enableCollision", "a", a);
        Check.notNull("World.enableCollision", "b", b);
        a.include(b);
        b.include(a);
        collisionFilterChanged(a, b);
    }

    /**
     * Whether {@link #disableCollision} keeps two bodies apart.
     *
     * @param a a body
     * @param b another body
     * @return true when their collision is disabled
     */
    public boolean isCollisionDisabled(Body a, Body b) {
        return a != null && b != null && a.excludes(b);
    }

    /**
     * Sets the application's collision filter, asked about pairs the built-in rules let collide
     * (see {@link CollisionFilter} for when, and what it may do). Every pair is asked again: contacts
     * the new filter refuses end at the next tick, and pairs the old one refused may then begin.
     * Not during a tick's pair search or solve (from the filter itself or a constraint).
     *
     * <pre>{@code
     * world.setCollisionFilter(new CollisionFilter() {
     *     public boolean shouldCollide(Body a, Body b) {
     *         // ghosts pass through everything but the walls (static bodies)
     *         return !(a.getUserData() instanceof Ghost && b.isDynamic()
     *             || b.getUserData() instanceof Ghost && a.isDynamic());
     *     }
     * });
     * }</pre>
     *
     * @param filter the filter, or null for the built-in rules alone (the default)
     */
    public void setCollisionFilter(CollisionFilter filter) {
        collisionFilter = filter;
        Body[] all = bodies.ordered();
        for (int i = 0, n = bodies.count(); i < n; i++) {
            proxies.filterChanged(all[i]);
        }
    }

    /**
     * The application's collision filter.
     *
     * @return the filter, or null when none is set
     */
    public CollisionFilter getCollisionFilter() {
        return collisionFilter;
    }

    /**
     * Asks the collision rules, the application's {@link CollisionFilter} included, again about
     * every pair of a body at the next tick, as a change of its layers or filter bits does: for when
     * the filter's answer for it changed.
     *
     * @param body a body of this world
     */
    public void refilter(Body body) {
        Check.notNull("World.refilter", "body", body);
        if (body.world != this) {
            throw new IllegalArgumentException("World.refilter: " + body + " is not in this world");
        }
        proxies.filterChanged(body);
    }

    /** The built-in rules, then the application's filter: whether two bodies may collide. */
    boolean shouldCollide(Body a, Body b) {
        return ContactManager.shouldCollide(a, b) && (collisionFilter == null || collisionFilter.shouldCollide(a, b));
    }

    private void collisionFilterChanged(Body a, Body b) {
        if (a.world == this) {
            proxies.filterChanged(a);
        }
        if (b.world == this) {
            proxies.filterChanged(b);
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
        constraints.add(constraint);
        sleep.wakeConstrained(constraint, this);
    }

    /**
     * Removes a constraint.
     *
     * @param constraint the constraint
     * @return true when it was in this world
     */
    public boolean removeConstraint(Constraint constraint) {
        boolean removed = constraints.remove(constraint);
        if (removed) {
            sleep.wakeConstrained(constraint, this);
        }
        return removed;
    }

    /**
     * The number of constraints.
     *
     * @return the count
     */
    public int getConstraintCount() {
        return constraints.count();
    }

    /**
     * A constraint by its position in the world's list (insertion order).
     *
     * @param index 0 to {@link #getConstraintCount()} − 1
     * @return the constraint
     */
    public Constraint getConstraint(int index) {
        return constraints.get(index);
    }

    private void removeConstraintsOf(Body body) {
        Constraint[] list = constraints.array();
        int kept = 0;
        for (int i = 0, n = constraints.count(); i < n; i++) {
            if (!list[i].concernsBody(body)) {
                list[kept++] = list[i];
            }
        }
        constraints.truncate(kept);
    }

    // ---------------------------------------------------------------------------------------------
    // What the world adds on top

    /**
     * The queue of structural changes made during a tick, for the world's own lists.
     *
     * @return the queue, open while a tick runs
     */
    protected final ChangeQueue changes() {
        return changes;
    }

    /**
     * Whether a body is in this world, or will be when the running tick ends.
     *
     * @param body the body
     * @return true when it is (will be) in this world
     */
    protected final boolean willContain(Body body) {
        boolean now = body.world == this;
        return changes.isOpen() ? changes.willContain(bodyChanges, body, now) : now;
    }

    /**
     * Called when a body has left the world, after its contacts and constraints, so that what the
     * world adds on top can forget it too.
     *
     * @param body the body removed
     */
    protected void bodyRemoved(Body body) {
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
     * The contact a handle names ({@link Contact#getHandle()}), while it lasts.
     *
     * @param handle a handle
     * @return the contact, or null when it has ended (or the handle is of no contact of this world)
     */
    public Contact findContact(long handle) {
        return contacts.find(handle);
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
     * What the last tick did: the bodies it simulated with their start poses, and the contacts that
     * began and stopped touching. Read-only; valid until the next tick.
     *
     * @return the step data
     */
    public StepData getStepData() {
        return stepData;
    }

    /**
     * Lets bodies fall asleep (off by default, as in the original engine, where nothing sleeps: a
     * world ported from it behaves as before; games with many resting bodies turn it on). Bodies
     * that moved slower than {@link SolverSettings#getSleepLinearTolerance()} and
     * {@link SolverSettings#getSleepAngularTolerance()} for {@link SolverSettings#getTimeToSleep()},
     * together with every body they touch or are constrained to, stop being simulated and cost
     * nothing until an awake body reaches them or the application changes them. Turning it off
     * wakes every body.
     *
     * @param enabled true to let bodies sleep
     */
    public void setSleepingEnabled(boolean enabled) {
        sleep.setEnabled(enabled, this);
    }

    /**
     * Splits every shared loop of a tick among the worker threads however little it holds, down to
     * parts of one contact or one body, in worlds of any size ({@link #setWorkerCount(int)}). Slower,
     * never faster: it is for tests. The results must be the same bit for bit at any worker count, and
     * with the usual thresholds a world of fewer than 400 simulated bodies never shares a tick, so a
     * test of a small world would check nothing; split, it checks every loop the threads share. Off by
     * default; turning it off restores the thresholds.
     *
     * @param split true to split everything
     */
    public void setSplitAlways(boolean split) {
        solver.setMinParallelPart(split ? 1 : Solver.MIN_BODIES, split ? 1 : ContactSolver.MIN_PART);
        contacts.minPart = split ? 1 : ContactManager.MIN_PART;
        proxies.setMinParallelPart(split ? 1 : Solver.MIN_BODIES);
        minThreadedBodies = split ? 0 : MIN_THREADED_BODIES;
    }

    /**
     * Whether every shared loop is split however little it holds ({@link #setSplitAlways}).
     *
     * @return false by default
     */
    public boolean isSplitAlways() {
        return minThreadedBodies == 0;
    }

    /** Whether the last tick shared its loops with worker threads (for tests). */
    boolean sharedLastTick() {
        return pool != null && !pool.isAlone();
    }

    /**
     * Shares each tick's contact solve with worker threads (1, the default, for none). The contacts
     * are solved colour by colour, so that the contacts of one colour share no moving body, and a
     * colour is split among the threads: the results are bit for bit those of one thread, for any
     * count. The narrowphase, the contacts' preparation and most per-body loops are shared too (the
     * threads set each contact's touching flag; the calling thread then destroys contacts and reports
     * touches, in the contacts' order; they mark the bodies whose broadphase boxes stay and those fast
     * enough to sweep, and the calling thread moves and sweeps those in order); the joints, the
     * colouring, the velocity integration and the broadphase's changes are not. Parts are at least 64 contacts in the
     * narrowphase, 32 in a colour and 256 bodies, and a tick with fewer than 400 simulated bodies runs on
     * the calling thread alone (the hand-offs would cost it more than they save; tests split everything with
     * {@link #setSplitAlways}). An idle thread spins about 80 µs, then parks:
     * between ticks, and within a tick while the calling thread does serial work longer than that.
     * The calling thread takes the parts no worker has taken once done with its own, so a parked
     * worker, or one the system does not schedule, never holds a tick up. Measured with two threads on
     * a 2-core virtual machine (`./emini bench`, two runs on 2026-11-29, session 15): ten 20-row
     * pyramids 1.79 times the one-thread speed, rain of 10,000 bodies 1.80, rain of 2,000 to 20,000
     * 1.4 to 2.1, the tumbler 1.3 to 1.46, when the host left both cores free; in a run where it took
     * the second core away at times, 0.89 to 0.96 times one: try it on the target device. Call with 1
     * to stop the threads when the world is no longer used.
     *
     * @param workers the threads that share the solve, counting the one that calls {@link #tick()}:
     *     1 to 64
     * @param factory makes the worker threads, or null for daemon threads named
     *     {@code emini-worker-N}
     */
    public void setWorkerCount(int workers, ThreadFactory factory) {
        if (changes.isOpen()) {
            throw new IllegalStateException("World.setWorkerCount: called during a tick; call it between ticks");
        }
        if (workers < 1 || workers > MAX_WORKERS) {
            throw new IllegalArgumentException("World.setWorkerCount: workers must be 1 to " + MAX_WORKERS + ", was "
                + workers);
        }
        if (pool != null) {
            pool.close();
            pool = null;
        }
        if (workers > 1) {
            pool = new WorkerPool(workers, factory);
        }
        solver.setPool(pool);
        contacts.setPool(pool);
        proxies.setPool(pool);
    }

    /**
     * Shares each tick's contact solve with daemon worker threads: see
     * {@link #setWorkerCount(int, ThreadFactory)}.
     *
     * @param workers the threads that share the solve, counting the calling one: 1 to 64
     */
    public void setWorkerCount(int workers) {
        setWorkerCount(workers, null);
    }

    /**
     * The threads that share the contact solve, counting the calling one.
     *
     * @return 1 when the world solves alone
     */
    public int getWorkerCount() {
        return pool == null ? 1 : pool.getThreadCount();
    }

    /**
     * Whether bodies may fall asleep.
     *
     * @return true when sleeping is on
     */
    public boolean isSleepingEnabled() {
        return sleep.isEnabled();
    }

    /**
     * Sets the listener that may leave touching contacts out of a tick's solve (one-way platforms).
     * Without one, nothing is called and nothing is paid.
     *
     * @param listener the listener, or null
     */
    public void setPreSolveListener(PreSolveListener listener) {
        preSolve = listener;
    }

    /**
     * The listener that may leave contacts out of a tick's solve.
     *
     * @return the listener, or null
     */
    public PreSolveListener getPreSolveListener() {
        return preSolve;
    }

    /**
     * Reports in the {@link StepData} every contact whose points took an impulse while approaching
     * faster than this speed along the normal (a hit, for sounds and damage), with its fastest point.
     *
     * @param speed the approach speed (px/s), &gt; 0; {@link Float#POSITIVE_INFINITY} (the default) turns hits off
     */
    public void setHitEventThreshold(float speed) {
        if (!(speed > 0f)) {
            throw new IllegalArgumentException("World.setHitEventThreshold: speed must be > 0, was " + speed);
        }
        hitEventThreshold = speed;
    }

    /**
     * The approach speed above which contacts are reported as hits.
     *
     * @return the speed (px/s), infinite when hits are off
     */
    public float getHitEventThreshold() {
        return hitEventThreshold;
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
     *
     * @throws IllegalStateException "World.tick: Body#id left the range of finite numbers in tick n
     *     (its state)" when extreme velocities, forces, gravity or a timestep carry a body's state past
     *     what a float holds; the bodies keep their last finite poses when the overflow is found before
     *     they are written back
     */
    public final void tick() {
        changes.open("World.tick: called during a tick (from an external force, a constraint or an event listener);"
            + " call it again after this one returns");
        try {
            step(timestep);
        } finally {
            stepData.end();
            solver.abort();
            changes.close();
        }
    }

    /**
     * One tick's work: collision detection and the solve, then the tick count grows. The world
     * applies external forces before it, and moves particles and checks events after it.
     *
     * @param dt the timestep (s)
     */
    protected void step(float dt) {
        stepData.begin(tickCount);
        area.collect(this, broadPhase, bodies.ordered(), bodies.count());
        if (pool != null) {
            pool.setAlone(area.count < minThreadedBodies);
        }
        stepData.recordStart(area.bodies, area.count);
        contacts.beginLandscape(landscape);
        Body overflow = proxies.update(area.bodies, area.count, settings.getAabbMargin(), dt);
        if (overflow != null) {
            throw leftFiniteRange(overflow, "position (" + overflow.x + ", " + overflow.y + "), velocity (" + overflow.vx
                + ", " + overflow.vy + ") px/s over a " + dt + " s timestep");
        }
        contacts.updatePairs(broadPhase);
        if (area.isBounded() || sleep.isEnabled()) {
            contacts.gather(area.bodies, area.count, tickCount);
        } else {
            contacts.gatherAll();
        }
        contacts.collide(broadPhase, dt * settings.getSpeculativeSweep(), settings.getSpeculativeDistance(), 0);
        if (sleep.isEnabled()) {
            wakeTouched(dt);
        }
        if (preSolve != null) {
            contacts.preSolve(preSolve);
        }
        Body bad = solver.solve(this, area.bodies, area.count, contacts.active, contacts.noPoints, contacts.activeCount,
            constraints.array(), constraints.count(), broadPhase);
        if (bad != null) {
            throw leftFiniteRange(bad, solver.bodies.describe(bad));
        }
        breakOverloaded();
        if (sleep.isEnabled()) {
            sleep.afterSolve(area.bodies, area.count, contacts.active, contacts.activeCount, constraints.array(),
                constraints.count(), settings, dt);
        }
        if (!sensors.isEmpty()) {
            sensors.update(this, stepData);
        }
        tickCount++;
    }

    /**
     * Removes, as the tick ends, every constraint whose force this tick exceeded its break force,
     * and lists it in the step data.
     */
    private void breakOverloaded() {
        Constraint[] list = constraints.array();
        for (int i = 0, n = constraints.count(); i < n; i++) {
            Constraint c = list[i];
            if (c.getForce() > c.getBreakForce() && removeConstraint(c)) {
                stepData.constraintBroke(c);
            }
        }
    }

    /**
     * Islands an awake body reached join this tick's solve, with their contacts (collided now), so
     * that the blow lands on moving bodies, as without sleep; until no more wake.
     */
    private void wakeTouched(float dt) {
        int from = 0;
        while (sleep.wakeTouched(contacts.active, from, contacts.activeCount)) {
            area.collect(this, broadPhase, bodies.ordered(), bodies.count());
            stepData.recordStart(area.bodies, area.count);
            from = contacts.gatherMore(area.bodies, area.count, tickCount);
            contacts.collide(broadPhase, dt * settings.getSpeculativeSweep(), settings.getSpeculativeDistance(), from);
        }
    }

    /** The tick's one error for a body whose state no float holds, with that state described. */
    private IllegalStateException leftFiniteRange(Body b, String state) {
        return new IllegalStateException("World.tick: Body#" + b.getId() + " left the range of finite numbers in tick "
            + tickCount + " (" + state + "); check the forces, velocities, gravity and timestep applied to it");
    }
}
