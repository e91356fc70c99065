package org.emini.dynamics;

/**
 * Where the copies of a world's bodies and constraints are, while a world is copied
 * ({@code World(World)}, {@code World.addWorld}): a copied constraint, force or event asks it for
 * the copies of what it refers to (the original's {@code copy(Body[] bodyMapping)}).
 */
public interface CopyMapping {
    /**
     * The copy of a body.
     *
     * @param original a body of the world being copied
     * @return its copy, or the body itself when it is not part of the copy (a sensor body outside
     *     the world)
     */
    Body body(Body original);

    /**
     * The copy of a constraint (copied before the events that refer to it).
     *
     * @param original a constraint of the world being copied
     * @return its copy
     */
    Constraint constraint(Constraint original);
}
