/**
 * The built-in constraints: {@link org.emini.constraint.Joint} (pin joints, loose or fixed),
 * {@link org.emini.constraint.Spring} (springs and rigid rods) and {@link org.emini.constraint.Motor}.
 *
 * <p>All are solved by the world's soft-step solver together with the contacts (see
 * {@link org.emini.dynamics.Constraint}): rigid constraints correct their position error with the
 * world's joint softness ({@link org.emini.dynamics.SolverSettings#getJointHertz()}) measured from
 * the bodies' motion since the tick began, so they do not drift; springs are soft constraints, stable
 * at any stiffness. Add them to the world with {@link org.emini.world.World#addConstraint}.
 */
package org.emini.constraint;
