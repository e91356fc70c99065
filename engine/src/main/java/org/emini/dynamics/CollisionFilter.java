package org.emini.dynamics;

/**
 * The application's own say in which pairs of bodies collide (Box2D's custom filter), set with
 * {@link Simulation#setCollisionFilter(CollisionFilter)}.
 *
 * <p>Asked only about pairs the built-in rules let collide (one body dynamic, both interacting, no
 * shared collision layer, Box2D's categories, masks and groups, {@link Simulation#disableCollision}),
 * and only while the pair has no contact: when the broadphase finds the pair (the first time their
 * fat boxes overlap, and again when either box is re-fitted while they overlap without a contact),
 * when a contact of the pair is checked again after a filter change of either body, and by the
 * fast-body sweep. Landscape contacts do not ask it.
 *
 * <p>It runs inside the tick, so it must be deterministic (the same answer for the same bodies and
 * state, whatever the call order), allocate nothing, and neither add nor remove bodies nor change
 * any body's filter. The two bodies may come in either order: answer the same for both. After
 * the answer changes for reasons of the application's own, call {@link Simulation#refilter(Body)}.
 */
public interface CollisionFilter {
    /**
     * Whether two bodies that the built-in rules let collide should collide.
     *
     * @param a a body
     * @param b another body
     * @return true to let them collide, false to let them pass through each other
     */
    boolean shouldCollide(Body a, Body b);
}
