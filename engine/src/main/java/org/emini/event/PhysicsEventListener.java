package org.emini.event;

/**
 * Receives the events of a world (the original engine's callback). Called from
 * {@link org.emini.world.World#tick()} after the bodies have moved; the listener must not add or
 * remove bodies, constraints or events during the call: note what to do and do it after the tick.
 */
public interface PhysicsEventListener {
    /**
     * An event's condition held in the tick that just ended.
     *
     * @param event the event
     * @param parameter what met the condition: the {@link org.emini.dynamics.Body} for position,
     *     velocity, angle, angular velocity and sensor events, the {@link org.emini.dynamics.Contact}
     *     for collision events, the {@link org.emini.dynamics.Constraint} for constraint-force events
     */
    void eventTriggered(Event event, Object parameter);
}
