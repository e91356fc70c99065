/**
 * Events: conditions on bodies, contacts and constraints that the world checks at the end of each
 * tick, telling a {@link org.emini.event.PhysicsEventListener} when they hold.
 *
 * <p>Create an {@link org.emini.event.Event} with one of its factories, add it with
 * {@link org.emini.world.World#addEvent} and register the listener with
 * {@link org.emini.world.World#setPhysicsEventListener}. Without a listener nothing is checked.
 */
package org.emini.event;
