package org.emini.io;

import org.emini.constraint.Joint;
import org.emini.constraint.Motor;
import org.emini.constraint.Spring;
import org.emini.constraint.TwoBodyConstraint;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;

/** Joints, springs and motors of a world file as engine constraints (see phy-mapping.md). */
final class ConstraintMapping {
    private ConstraintMapping() {
    }

    static UnsupportedElement.Kind kind(PhyConstraint c) {
        return c instanceof PhyJoint ? UnsupportedElement.Kind.JOINT
                : c instanceof PhySpring ? UnsupportedElement.Kind.SPRING : UnsupportedElement.Kind.MOTOR;
    }

    /**
     * Builds a constraint on the bodies built so far, or lists it.
     *
     * @param timestep the world's timestep: a motor's cap is an impulse per tick in the original
     * @return the constraint, or null when it is not built
     */
    static Constraint build(PhyConstraint c, int index, BuildResult r, float timestep) {
        UnsupportedElement.Kind kind = kind(c);
        try {
            if (c instanceof PhyPairConstraint) {
                PhyPairConstraint p = (PhyPairConstraint) c;
                Body a = body(p.getBody1(), kind, index, r);
                Body b = body(p.getBody2(), kind, index, r);
                if (a == null || b == null) {
                    return null;
                }
                float ax = p.getAnchor1().getX();
                float ay = p.getAnchor1().getY();
                float bx = p.getAnchor2().getX();
                float by = p.getAnchor2().getY();
                if (c instanceof PhyJoint) {
                    return new Joint(a, b, ax, ay, bx, by, ((PhyJoint) c).isFixed());
                }
                PhySpring s = (PhySpring) c;
                Spring spring = new Spring(a, b, ax, ay, bx, by, s.getRestLength());
                if (!s.isRigid()) {
                    spring.setCoefficient(s.getCoefficient());
                }
                return spring;
            }
            PhyMotor m = (PhyMotor) c;
            Body body = body(m.getBody(), kind, index, r);
            if (body == null) {
                return null;
            }
            // The original clamps the impulse accumulated over a tick; the engine limits the force.
            float cap = m.getMaxForce() / timestep;
            Motor motor = m.isRotational() ? new Motor(body, -m.getTargetAngularVelocity(), cap)
                    : new Motor(body, m.getTargetVelocity().getX(), m.getTargetVelocity().getY(), cap);
            if (!m.isRotational()) {
                motor.setRelative((m.getFlags() & PhyMotor.FLAG_RELATIVE) != 0);
                motor.setOrthogonal((m.getFlags() & PhyMotor.FLAG_FIX_ORTHOGONAL) != 0);
            }
            return motor;
        } catch (IllegalArgumentException e) {
            r.unsupported(kind, index, e.getMessage());
            return null;
        }
    }

    /** Attaches a record's user data to a constraint this class built (a joint, spring or motor). */
    static void setUserData(Constraint c, Object data) {
        if (c instanceof Motor) {
            ((Motor) c).setUserData(data);
        } else {
            ((TwoBodyConstraint) c).setUserData(data);
        }
    }

    private static Body body(int i, UnsupportedElement.Kind kind, int index, BuildResult r) {
        Body b = r.bodyAt(i);
        if (b == null) {
            r.unsupported(kind, index, BuildResult.missing("body", i, r.getDocument().getBodies().size()));
        }
        return b;
    }
}
