/**
 * The built-in constraints: the manual's {@link org.emini.constraint.Joint} (pin joints, loose or
 * fixed, the fixed one optionally soft), {@link org.emini.constraint.Spring} (springs and rigid rods)
 * and {@link org.emini.constraint.Motor}; and the joints of Box2D-style games:
 * {@link org.emini.constraint.RevoluteJoint}, {@link org.emini.constraint.PrismaticJoint},
 * {@link org.emini.constraint.WheelJoint}, {@link org.emini.constraint.MouseJoint},
 * {@link org.emini.constraint.DistanceJoint} and {@link org.emini.constraint.MotorJoint}. Every one
 * may be made breakable ({@code setBreakForce}).
 *
 * <p>All are solved by the world's soft-step solver together with the contacts (see
 * {@link org.emini.dynamics.Constraint}): rigid constraints correct their position error with the
 * world's joint softness ({@link org.emini.dynamics.SolverSettings#getJointHertz()}) measured from
 * the bodies' motion since the tick began, so they do not drift; springs are soft constraints, stable
 * at any stiffness. Add them to the world with {@link org.emini.world.World#addConstraint}.
 */
package org.emini.constraint;
