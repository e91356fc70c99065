package org.emini.io;

import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.event.Event;
import org.emini.math.EMath;
import org.emini.shape.Shape;

/** Events of a world file as engine events (see phy-mapping.md). */
final class EventMapping {
    private EventMapping() {
    }

    /**
     * Builds an event on the bodies, shapes and constraints built so far, or lists it.
     *
     * @param sensor the sensor body of a sensor event (not in the world), or null
     * @param timestep the world's timestep: the original's constraint-force events compare an
     *     impulse per tick
     * @return the event, or null when it is not built
     */
    static Event build(PhyEvent e, int index, BuildResult r, Body sensor, float timestep) {
        Body body = null;
        Shape shape = null;
        Constraint constraint = null;
        PhyWorld doc = r.getDocument();
        if (e.getBodyFilter() != PhyWorld.NONE && (body = r.bodyAt(e.getBodyFilter())) == null) {
            return missing(r, index, BuildResult.missing("body", e.getBodyFilter(), doc.getBodies().size()));
        }
        if (e.getShapeFilter() != PhyWorld.NONE && (shape = r.shapeAt(e.getShapeFilter())) == null) {
            return missing(r, index, BuildResult.missing("shape", e.getShapeFilter(), doc.getShapes().size()));
        }
        if (e.getConstraintFilter() != PhyWorld.NONE
                && (constraint = r.constraintAt(e.getConstraintFilter())) == null) {
            return missing(r, index, BuildResult.missing("constraint", e.getConstraintFilter(),
                    doc.getConstraints().size()));
        }
        float a = PhyFixed.fx(e.getTargetRaw(0));
        float b = PhyFixed.fx(e.getTargetRaw(1));
        float c = PhyFixed.fx(e.getTargetRaw(2));
        float d = PhyFixed.fx(e.getTargetRaw(3));
        float a2 = PhyFixed.fx2(e.getTargetRaw(0));
        float b2 = PhyFixed.fx2(e.getTargetRaw(1));
        Event event;
        try {
            switch (e.getType()) {
                case PhyEvent.TYPE_BODY_POSITION:
                    event = Event.createPositionEvent(body, shape, a, b, c, d);
                    break;
                case PhyEvent.TYPE_BODY_VELOCITY:
                    // The original compares the squared speed.
                    event = Event.createVelocityEvent(body, shape, EMath.sqrt(Math.max(a, 0f)),
                            b < 0f ? -1f : EMath.sqrt(b));
                    break;
                case PhyEvent.TYPE_BODY_ROTATION:
                    event = Event.createAngleEvent(body, shape, a2, b2);
                    break;
                case PhyEvent.TYPE_BODY_ANGULAR_VELOCITY:
                    // The original's sign: its [min, max] is the engine's [−max, −min].
                    event = Event.createAngularVelocityEvent(body, shape, -b2, -a2);
                    break;
                case PhyEvent.TYPE_BODY_COLLISION:
                    event = Event.createCollisionEvent(body, shape, e.getTargetRaw(0) > 0, e.getTargetRaw(1) > 0,
                            e.getTargetRaw(2) > 0, e.getTargetRaw(3) > 0);
                    break;
                case PhyEvent.TYPE_BODY_COLLISION_RELATIVE:
                    event = relative(body, shape, a2, b);
                    break;
                case PhyEvent.TYPE_BODY_SENSOR:
                    if (sensor == null) {
                        return missing(r, index, "its sensor body is not built");
                    }
                    event = Event.createSensorEvent(body, shape, sensor);
                    break;
                case PhyEvent.TYPE_CONSTRAINT_FORCE:
                    event = Event.createConstraintForceEvent(constraint, a / timestep, b / timestep);
                    r.approximated(UnsupportedElement.Kind.EVENT, index, "the original compares an impulse "
                            + "measure per tick (a rigid spring's summed since it was made); built as the force "
                            + "over the tick");
                    break;
                default:
                    r.unsupported(UnsupportedElement.Kind.EVENT, index, "event type " + e.getType()
                            + " is not defined");
                    return null;
            }
        } catch (IllegalArgumentException x) {
            r.unsupported(UnsupportedElement.Kind.EVENT, index, x.getMessage());
            return null;
        }
        event.setTriggerOnce(e.isTriggerOnce());
        return event;
    }

    /**
     * The original's relative collision: the unit vector from the contact point to the body has a
     * dot product ≥ minCos with the direction at angle + body angle. The engine measures from the
     * body to the point (the original's angle plus π) over a range of half-width acos(minCos).
     */
    private static Event relative(Body body, Shape shape, float angle, float minCos) {
        if (minCos > 1f) {
            throw new IllegalArgumentException("a minimum cosine of " + minCos + " never holds");
        }
        float half = minCos <= -1f ? EMath.PI : EMath.atan2(EMath.sqrt(1f - minCos * minCos), minCos);
        float centre = angle + EMath.PI;
        return Event.createRelativeCollisionEvent(body, shape, centre - half, centre + half);
    }

    private static Event missing(BuildResult r, int index, String reason) {
        r.unsupported(UnsupportedElement.Kind.EVENT, index, reason);
        return null;
    }
}
