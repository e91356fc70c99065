package org.emini.world;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.Contact;
import org.emini.dynamics.CopyMapping;
import org.emini.dynamics.Landscape;
import org.emini.dynamics.Simulation;
import org.emini.event.Event;
import org.emini.event.PhysicsEventListener;
import org.emini.event.Script;
import org.emini.event.ScriptHost;
import org.emini.internal.ChangeQueue;
import org.emini.internal.Check;
import org.emini.internal.ElementList;
import org.emini.particle.ParticleEmitter;
import org.emini.particle.ParticleSystem;
import org.emini.shape.ShapeSet;

/**
 * The simulated world of the manual: bodies, gravity, the solver's settings, and {@link #tick()}.
 * The physics (bodies, constraints, contacts, the landscape, the simulation area, the solve) is
 * {@link Simulation}'s; the world adds what acts before the solve, {@linkplain ExternalForce
 * external forces}, and what reads its result after it: {@linkplain ParticleEmitter particles},
 * then {@linkplain Event events} when a listener is set.
 *
 * <p>Defaults are the original engine's: 20 ticks per second, 10 iterations, gravity (0, 100) px/s²
 * pointing down the screen, no damping. Structural changes made during a tick wait for its end, as
 * {@link Simulation} describes; so do those of forces, events and emitters.
 *
 * <p>An application may extend it, as the manual's {@code GraphicsWorld} does: a subclass adds its
 * own fields and methods (drawing, game state) and may override the public methods to observe them
 * (calling {@code super}). What a tick does and in which order is the engine's: {@link #tick()} and
 * the steps inside it are final. The copy constructor {@link #World(World)} lets a subclass wrap a
 * world loaded from a file.
 *
 * <pre>{@code
 * World world = new World();
 * world.addBody(new Body(0, 10, Shape.createRectangle(400, 20), false));   // static ground
 * Body box = new Body(0, -100, Shape.createRectangle(20, 20), true);
 * world.addBody(box);
 * for (int i = 0; i < 60; i++) {
 *     world.tick();                                                      // 1/20 s each
 * }
 * }</pre>
 */
public class World extends Simulation implements ScriptHost {
    private final ElementList<ExternalForce> forces = new ElementList<ExternalForce>(changes(), new ExternalForce[4],
        "ExternalForce", "force");
    private final ElementList<Event> events = new ElementList<Event>(changes(), new Event[4], "Event", "event");
    private PhysicsEventListener eventListener;
    private final ParticleSystem particles = new ParticleSystem();
    private final ChangeQueue.Target emitterChanges = new ChangeQueue.Target() {
        @Override
        public void apply(Object item, boolean add) {
            if (add) {
                addParticleEmitter((ParticleEmitter) item);
            } else {
                removeParticleEmitter((ParticleEmitter) item);
            }
        }
    };

    private Object userData;
    private ShapeSet shapeSet = new ShapeSet();
    private final ArrayList<Script> scripts = new ArrayList<Script>();
    private ScriptRun[] runs = new ScriptRun[4];
    private int runCount;

    /** Creates an empty world with the original engine's defaults. */
    public World() {
    }

    /**
     * Creates a copy of a world (the original's {@code World(World)}): its settings, solver
     * settings, landscape (copied), shape set and user data (shared), and a copy of everything in it
     * as {@link #addWorld} makes it. The listener, the collision filter, the pre-solve listener and
     * pair exclusions made with {@code disableCollision} are not copied. Shapes are shared, as in
     * the original.
     *
     * @param other the world to copy, not ticking
     * @throws UnsupportedOperationException when it holds a constraint that cannot be copied
     *     ({@link Constraint#copy})
     */
    public World(World other) {
        Check.notNull("World(World)", "other", other);
        WorldSettings.copy(other, this);
        // addWorld adds the segments; the material is the world's own.
        getLandscape().setFriction(other.getLandscape().getFriction());
        getLandscape().setElasticity(other.getLandscape().getElasticity());
        shapeSet = other.shapeSet;
        userData = other.userData;
        addWorld(other);
    }

    /**
     * Adds a copy of everything in another world to this one (the original's {@code addWorld}): its
     * bodies ({@link Body#copy()}: shapes and user data shared), then its constraints, external
     * forces, events, scripts and the scripts running (where they are), each on the copies of its
     * bodies. The other world's landscape
     * segments are added to this world's landscape (whose material stays this world's). Particle
     * emitters are not copied. The other world is not changed.
     *
     * @param other the world to copy in, not ticking and not this one
     * @return the copies of its bodies: element i is the copy of {@code other.getBody(i)}
     * @throws UnsupportedOperationException when it holds a constraint that cannot be copied
     *     ({@link Constraint#copy}); nothing has been added then
     */
    public Body[] addWorld(World other) {
        Check.notNull("World.addWorld", "other", other);
        if (other == this) {
            throw new IllegalArgumentException("World.addWorld: a world cannot add itself");
        }
        final IdentityHashMap<Body, Body> bodies = new IdentityHashMap<Body, Body>();
        final IdentityHashMap<Constraint, Constraint> constraints = new IdentityHashMap<Constraint, Constraint>();
        CopyMapping mapping = new CopyMapping() {
            @Override
            public Body body(Body original) {
                Body copy = bodies.get(original);
                return copy != null ? copy : original;
            }

            @Override
            public Constraint constraint(Constraint original) {
                Constraint copy = constraints.get(original);
                return copy != null ? copy : original;
            }
        };
        Body[] copies = new Body[other.getBodyCount()];
        for (int i = 0; i < copies.length; i++) {
            copies[i] = other.getBody(i).copy();
            bodies.put(other.getBody(i), copies[i]);
        }
        // Constraints need their bodies in a world: copy them into a scratch world first, so a
        // constraint that cannot be copied leaves this world unchanged.
        World scratch = new World();
        for (Body copy : copies) {
            scratch.addBody(copy);
        }
        Constraint[] copiedConstraints = new Constraint[other.getConstraintCount()];
        for (int i = 0; i < copiedConstraints.length; i++) {
            Constraint original = other.getConstraint(i);
            copiedConstraints[i] = original.copy(mapping);
            constraints.put(original, copiedConstraints[i]);
        }
        for (Body copy : copies) {
            scratch.removeBody(copy);
        }
        for (Body copy : copies) {
            addBody(copy);
        }
        for (Constraint c : copiedConstraints) {
            addConstraint(c);
        }
        for (int i = 0; i < other.getExternalForceCount(); i++) {
            addExternalForce(other.getExternalForce(i).copy(mapping));
        }
        for (int i = 0; i < other.getEventCount(); i++) {
            addEvent(other.getEvent(i).copy(mapping));
        }
        for (Script script : other.scripts) {
            addScript(script);
        }
        for (int i = 0; i < other.runCount; i++) {
            startRun(new ScriptRun(other.runs[i], mapping.body(other.runs[i].body)));
        }
        Landscape from = other.getLandscape();
        Landscape to = getLandscape();
        for (int i = 0; i < from.getSegmentCount(); i++) {
            to.addSegment(from.getStartX(i), from.getStartY(i), from.getEndX(i), from.getEndY(i), from.getFace(i));
        }
        return copies;
    }

    /**
     * The bodies in a new array, in the world's order (the original's {@code getBodies()}; here the
     * order is insertion order and does not change from tick to tick). Allocates: in a loop that
     * runs every tick use {@link #getBodyCount()} and {@link #getBody(int)}.
     *
     * @return the bodies, {@link #getBodyCount()} of them
     */
    public Body[] getBodies() {
        Body[] out = new Body[getBodyCount()];
        for (int i = 0; i < out.length; i++) {
            out[i] = getBody(i);
        }
        return out;
    }

    /**
     * The constraints in a new array, in insertion order (the original's {@code getConstraints()}).
     * Allocates, as {@link #getBodies()} does.
     *
     * @return the constraints, {@link #getConstraintCount()} of them
     */
    public Constraint[] getConstraints() {
        Constraint[] out = new Constraint[getConstraintCount()];
        for (int i = 0; i < out.length; i++) {
            out[i] = getConstraint(i);
        }
        return out;
    }

    /**
     * A body's contacts of the last tick in a new array (the original's
     * {@code getContactsForBody}); valid until the next tick. Allocates: a game that asks every tick
     * can use {@link Body#getContacts(Contact[])} with its own array.
     *
     * @param body a body of this world
     * @return its contacts, touching or not (see {@link Contact#isTouching()})
     */
    public Contact[] getContactsForBody(Body body) {
        Check.notNull("World.getContactsForBody", "body", body);
        Contact[] out = new Contact[body.getContactCount()];
        int n = body.getContacts(out);
        return n == out.length ? out : Arrays.copyOf(out, n);
    }

    /**
     * Sets gravity straight down the screen, the original's {@code setGravity(int)}.
     *
     * @param gravity the y component (px/s²); the x component becomes 0
     */
    public void setGravity(int gravity) {
        setGravity(0f, gravity);
    }

    /**
     * The application's object attached to the world.
     *
     * @return the user data, or null
     */
    public Object getUserData() {
        return userData;
    }

    /**
     * Attaches an application object to the world (a loaded world gets the world record's).
     *
     * @param userData any object, or null
     */
    public void setUserData(Object userData) {
        this.userData = userData;
    }

    /**
     * The world's numbered shapes, the original's {@code getShapeSet()}: a world loaded from a file
     * holds the file's shapes in file order (their ids); the application may register more.
     *
     * @return the shape set, never null
     */
    public ShapeSet getShapeSet() {
        return shapeSet;
    }

    /**
     * Replaces the shape set, for an application that keeps its own data in a subclass of it (the
     * manual's {@code GraphicsShapeSet}); the shapes of the old set are registered in it in their
     * order.
     *
     * @param set the new set
     */
    public void setShapeSet(ShapeSet set) {
        Check.notNull("World.setShapeSet", "set", set);
        for (int i = 0; i < shapeSet.getShapeCount(); i++) {
            set.register(shapeSet.getShape(i));
        }
        shapeSet = set;
    }

    /**
     * A body's mechanical energy (the original's {@code getBodyTotalEnergyFX}): kinetic energy
     * ½·m·v² + ½·I·ω² plus the potential energy in the world's gravity, −m·(g·p), zero at the
     * origin. A static body has none.
     *
     * @param body the body
     * @return the energy (mass·px²/s²)
     */
    public float getBodyTotalEnergy(Body body) {
        Check.notNull("World.getBodyTotalEnergy", "body", body);
        if (!body.isDynamic()) {
            return 0f;
        }
        float potential = -body.getMass() * (getGravityX() * body.getX() + getGravityY() * body.getY());
        return body.getKineticEnergy() + (body.isAffectedByGravity() ? potential : 0f);
    }

    /**
     * The world's mechanical energy: every body's {@link #getBodyTotalEnergy} plus the elastic
     * energy ½·k·(d − d₀)² of the springs given a coefficient ({@link Spring#setCoefficient}). In a
     * world without friction, damping, inelastic impacts and motors it stays constant up to the
     * integrator's error.
     *
     * @return the energy (mass·px²/s²)
     */
    public float getTotalEnergy() {
        float e = 0f;
        for (int i = 0, n = getBodyCount(); i < n; i++) {
            e += getBodyTotalEnergy(getBody(i));
        }
        for (int i = 0, n = getConstraintCount(); i < n; i++) {
            Constraint c = getConstraint(i);
            if (c instanceof Spring) {
                Spring spring = (Spring) c;
                float stretch = spring.getLength() - spring.getRestLength();
                e += 0.5f * spring.getCoefficient() * stretch * stretch;
            }
        }
        return e;
    }

    @Override
    protected final void step(float dt) {
        runScripts(dt);
        for (int i = 0, n = forces.count(); i < n; i++) {
            forces.get(i).applyForce(this, dt);
        }
        super.step(dt);
        if (particles.getEmitterCount() > 0) {
            particles.step(this, dt);
        }
        if (eventListener != null) {
            for (int i = 0, n = events.count(); i < n; i++) {
                events.get(i).check(this, eventListener);
            }
        }
    }

    @Override
    protected final void bodyRemoved(Body body) {
        particles.removeEmittersOf(body);
        stopRuns(body, null);
    }

    // ---------------------------------------------------------------------------------------------
    // Scripts

    /** Runs one tick of every running script, at the start of the tick; ended runs are dropped. */
    private void runScripts(float dt) {
        int kept = 0;
        for (int i = 0; i < runCount; i++) {
            ScriptRun run = runs[i];
            if (run.step(dt)) {
                runs[kept++] = run;
            }
        }
        Arrays.fill(runs, kept, runCount, null);
        runCount = kept;
    }

    /**
     * Adds a script to the world's list (the original's {@code addScript}), where a world file
     * keeps its scripts; {@link #applyScript} runs one.
     *
     * @param script the script
     */
    public void addScript(Script script) {
        Check.notNull("World.addScript", "script", script);
        if (!scripts.contains(script)) {
            scripts.add(script);
        }
    }

    /**
     * Removes a script from the world's list and stops its runs.
     *
     * @param script the script
     * @return true when it was in the list
     */
    public boolean removeScript(Script script) {
        stopRuns(null, script);
        return scripts.remove(script);
    }

    /** Drops the runs on a body or of a script (null matches nothing), keeping the others' order. */
    private void stopRuns(Body body, Script script) {
        int kept = 0;
        for (int i = 0; i < runCount; i++) {
            if (runs[i].body != body && runs[i].script != script) {
                runs[kept++] = runs[i];
            }
        }
        Arrays.fill(runs, kept, runCount, null);
        runCount = kept;
    }

    /**
     * The number of scripts in the world's list.
     *
     * @return the count
     */
    public int getScriptCount() {
        return scripts.size();
    }

    /**
     * A script by its position in the world's list.
     *
     * @param index 0 to {@link #getScriptCount()} − 1
     * @return the script
     */
    public Script getScript(int index) {
        return scripts.get(index);
    }

    /**
     * Runs a script on a body (the original's {@code script.applyToBody(body, world)}): from the
     * next tick on, each tick starts with the script's current element applied to the body. The
     * script joins the world's list. Unlike the original's fixed 32 runs, any number may run.
     *
     * @param script the script
     * @param body a body of this world
     */
    @Override
    public void applyScript(Script script, Body body) {
        Check.notNull("World.applyScript", "script", script);
        Check.notNull("World.applyScript", "body", body);
        if (!willContain(body)) {
            throw new IllegalArgumentException("World.applyScript: " + body + " is not in this world");
        }
        addScript(script);
        startRun(new ScriptRun(script, body));
    }

    private void startRun(ScriptRun run) {
        if (runCount == runs.length) {
            runs = Arrays.copyOf(runs, 2 * runCount);
        }
        runs[runCount++] = run;
    }

    /**
     * The number of script runs in progress.
     *
     * @return the count
     */
    public int getRunningScriptCount() {
        return runCount;
    }

    /**
     * The script of a run in progress.
     *
     * @param index 0 to {@link #getRunningScriptCount()} − 1, in the order the runs started
     * @return the script
     */
    public Script getRunningScript(int index) {
        return run(index).script;
    }

    /**
     * The body a run in progress moves.
     *
     * @param index 0 to {@link #getRunningScriptCount()} − 1, in the order the runs started
     * @return the body
     */
    public Body getRunningScriptBody(int index) {
        return run(index).body;
    }

    private ScriptRun run(int index) {
        if (index < 0 || index >= runCount) {
            throw new IndexOutOfBoundsException("World: script run " + index + " of " + runCount);
        }
        return runs[index];
    }

    // ---------------------------------------------------------------------------------------------
    // External forces

    /**
     * Adds an external force, applied at the start of every tick before anything moves.
     *
     * @param force the force
     */
    public void addExternalForce(ExternalForce force) {
        forces.add(force);
    }

    /**
     * Removes an external force.
     *
     * @param force the force
     * @return true when it was in this world
     */
    public boolean removeExternalForce(ExternalForce force) {
        return forces.remove(force);
    }

    /**
     * The number of external forces.
     *
     * @return the count
     */
    public int getExternalForceCount() {
        return forces.count();
    }

    /**
     * An external force by its position in the world's list (insertion order).
     *
     * @param index 0 to {@link #getExternalForceCount()} − 1
     * @return the force
     */
    public ExternalForce getExternalForce(int index) {
        return forces.get(index);
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
        events.add(event);
    }

    /**
     * Removes an event.
     *
     * @param event the event
     * @return true when it was in this world
     */
    public boolean removeEvent(Event event) {
        return events.remove(event);
    }

    /**
     * The number of events.
     *
     * @return the count
     */
    public int getEventCount() {
        return events.count();
    }

    /**
     * An event by its position in the world's list (insertion order); the position is the
     * original engine's event id.
     *
     * @param index 0 to {@link #getEventCount()} − 1
     * @return the event
     */
    public Event getEvent(int index) {
        return events.get(index);
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
        if (b != null && !willContain(b)) {
            throw new IllegalArgumentException("World.addParticleEmitter: the emitter's body " + b + " is not in this world");
        }
        ChangeQueue changes = changes();
        boolean owned = ParticleSystem.isOwned(emitter);
        if (changes.isOpen() ? changes.willContain(emitterChanges, emitter, owned) : owned) {
            throw new IllegalArgumentException("World.addParticleEmitter: " + emitter + " already belongs to a world");
        }
        if (changes.isOpen()) {
            changes.add(emitterChanges, emitter, true);
        } else if (!particles.addEmitter(emitter)) {
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
        ChangeQueue changes = changes();
        if (changes.isOpen()) {
            boolean there = emitter != null && changes.willContain(emitterChanges, emitter, particles.contains(emitter));
            if (there) {
                changes.add(emitterChanges, emitter, false);
            }
            return there;
        }
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
}
