package org.emini.world;

import org.emini.dynamics.Body;
import org.emini.dynamics.Simulation;
import org.emini.event.Event;
import org.emini.event.PhysicsEventListener;
import org.emini.internal.ChangeQueue;
import org.emini.internal.Check;
import org.emini.internal.ElementList;
import org.emini.particle.ParticleEmitter;
import org.emini.particle.ParticleSystem;

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
 */
public final class World extends Simulation {
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

    /** Creates an empty world with the original engine's defaults. */
    public World() {
    }

    @Override
    protected void step(float dt) {
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
    protected void bodyRemoved(Body body) {
        particles.removeEmittersOf(body);
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
