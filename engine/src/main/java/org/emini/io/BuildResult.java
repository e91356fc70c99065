package org.emini.io;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.world.World;
import org.emini.event.Event;
import org.emini.particle.ParticleEmitter;
import org.emini.shape.Shape;

/**
 * What {@link WorldBuilder} made of a document: the world, the engine objects by their index in
 * the document, the application's user-data objects, and the records that were left out or
 * approximated.
 */
public final class BuildResult {
    private final PhyWorld document;
    private final World world;
    private final Shape[] shapes;
    private final Body[] bodies;
    private final Constraint[] constraints;
    private final Event[] events;
    private final ParticleEmitter[] emitters;
    private final Map<PhyElement, Object> userData = new IdentityHashMap<PhyElement, Object>();
    private final List<UnsupportedElement> unsupported = new ArrayList<UnsupportedElement>();
    private final List<UnsupportedElement> approximations = new ArrayList<UnsupportedElement>();

    BuildResult(PhyWorld document, World world) {
        this.document = document;
        this.world = world;
        shapes = new Shape[document.getShapes().size()];
        bodies = new Body[document.getBodies().size()];
        constraints = new Constraint[document.getConstraints().size()];
        events = new Event[document.getEvents().size()];
        emitters = new ParticleEmitter[document.getParticleEmitters().size()];
    }

    /**
     * The document the world was built from.
     *
     * @return the document
     */
    public PhyWorld getDocument() {
        return document;
    }

    /**
     * The world.
     *
     * @return the built world
     */
    public World getWorld() {
        return world;
    }

    /**
     * The engine shape built for a shape-list entry (shared by all bodies using it).
     *
     * @param index the entry's index in {@link PhyWorld#getShapes()}
     * @return the shape, or null when the entry is not built (see {@link #getUnsupported()})
     */
    public Shape getShape(int index) {
        return shapes[index];
    }

    /**
     * The body built for a body record.
     *
     * @param index the record's index in {@link PhyWorld#getBodies()} (file order)
     * @return the body, or null when the record is not built (see {@link #getUnsupported()})
     */
    public Body getBody(int index) {
        return bodies[index];
    }

    /**
     * The joint, spring or motor built for a constraint record.
     *
     * @param index the record's index in {@link PhyWorld#getConstraints()}
     * @return the constraint, or null when the record is not built (see {@link #getUnsupported()})
     */
    public Constraint getConstraint(int index) {
        return constraints[index];
    }

    /**
     * The event built for an event record (the original's event id is its index). Events are
     * checked only while the world has a listener ({@link World#setPhysicsEventListener}).
     *
     * @param index the record's index in {@link PhyWorld#getEvents()}
     * @return the event, or null when the record is not built (see {@link #getUnsupported()})
     */
    public Event getEvent(int index) {
        return events[index];
    }

    /**
     * The particle emitter built for an emitter record.
     *
     * @param index the record's index in {@link PhyWorld#getParticleEmitters()}
     * @return the emitter, or null when the record is not built (see {@link #getUnsupported()})
     */
    public ParticleEmitter getParticleEmitter(int index) {
        return emitters[index];
    }

    /**
     * The object the {@link UserData} factory made for a record's user-data string.
     *
     * @param element a record of the document (a shape, body, constraint, event, sensor body,
     *     emitter or the world record)
     * @return the object, or null when there is none (no factory, the version stores no string,
     *     or the factory returned null)
     */
    public Object getUserData(PhyElement element) {
        return userData.get(element);
    }

    /**
     * The records left out of the world, in document order by kind.
     *
     * @return an unmodifiable list
     */
    public List<UnsupportedElement> getUnsupported() {
        return Collections.unmodifiableList(unsupported);
    }

    /**
     * The number of records of one kind left out of the world.
     *
     * @param kind the kind
     * @return the count
     */
    public int getUnsupportedCount(UnsupportedElement.Kind kind) {
        int n = 0;
        for (UnsupportedElement e : unsupported) {
            if (e.getKind() == kind) {
                n++;
            }
        }
        return n;
    }

    /**
     * The records built in an approximated form (e.g. a line shape built as a thin slab, a
     * material factor clamped to [0, 1]).
     *
     * @return an unmodifiable list
     */
    public List<UnsupportedElement> getApproximations() {
        return Collections.unmodifiableList(approximations);
    }

    /** The shape built for an entry; null when not built or when the index names no entry. */
    Shape shapeAt(int index) {
        return index >= 0 && index < shapes.length ? shapes[index] : null;
    }

    /** The body built for a record; null when not built or when the index names no record. */
    Body bodyAt(int index) {
        return index >= 0 && index < bodies.length ? bodies[index] : null;
    }

    /** The constraint built for a record; null when not built or when the index names no record. */
    Constraint constraintAt(int index) {
        return index >= 0 && index < constraints.length ? constraints[index] : null;
    }

    /** Why a reference yields nothing: the record is not built, or there is no such record. */
    static String missing(String what, int index, int count) {
        return "its " + what + " " + index + (index < count ? " is not built" : " does not exist");
    }

    void setShape(int index, Shape shape) {
        shapes[index] = shape;
    }

    void setBody(int index, Body body) {
        bodies[index] = body;
    }

    void setConstraint(int index, Constraint constraint) {
        constraints[index] = constraint;
    }

    void setEvent(int index, Event event) {
        events[index] = event;
    }

    void setParticleEmitter(int index, ParticleEmitter emitter) {
        emitters[index] = emitter;
    }

    void putUserData(PhyElement element, Object data) {
        userData.put(element, data);
    }

    void unsupported(UnsupportedElement.Kind kind, int index, String reason) {
        unsupported.add(new UnsupportedElement(kind, index, reason));
    }

    void approximated(UnsupportedElement.Kind kind, int index, String reason) {
        approximations.add(new UnsupportedElement(kind, index, reason));
    }

    @Override
    public String toString() {
        return "BuildResult[" + world.getBodyCount() + " bodies, " + unsupported.size() + " unsupported, "
                + approximations.size() + " approximated]";
    }
}
