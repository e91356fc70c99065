package org.emini.constraint;

import org.emini.dynamics.SolverStep;

/**
 * Rows on the relative angle of a joint's bodies, B's angle minus A's: torques, with their reaction
 * on A.
 *
 * <p>For a hinge the rows can be projected off its pin ({@link #projectOffPin}): a bare torque on a
 * small bob at the end of a long arm turns the bob about its own centre, which the pin then undoes
 * (the pin's effective mass is hundreds of times the bob's own inertia there, and one pass of each
 * per substep let a pendulum pass its angle limit by 0.06 rad and bounce). The projected row adds to
 * the torque the linear impulse at the anchors that leaves the pin's velocity unchanged, and uses
 * the matching effective mass (the Schur complement of the pin's block): the rows then act on the
 * rotation about the pin, and the pin and the rows no longer undo each other. While the pin holds,
 * the projected row's velocity is the same dθ/dt.
 */
final class AngularAxis extends AxisRows {
    private final TwoBodyConstraint joint;
    private boolean projected;
    // The linear impulse per unit of torque (world axes) the projected row adds at the anchors.
    private float lx;
    private float ly;
    // The tick's sum of those linear impulses, part of the joint's force.
    float tickLinearX;
    float tickLinearY;

    AngularAxis(TwoBodyConstraint joint) {
        this.joint = joint;
    }

    /** Starts a tick: the effective mass is 1/(1/I_A + 1/I_B). */
    void prepare(SolverStep step) {
        projected = false;
        tickLinearX = 0f;
        tickLinearY = 0f;
        prepare(joint.iA + joint.iB, joint.radius, step);
    }

    /**
     * Projects the rows off the pin that holds the joint's anchors together, for the arms of this
     * pass (the joint's arms() must have run).
     */
    void projectOffPin() {
        TwoBodyConstraint j = joint;
        float iA = j.iA;
        float iB = j.iB;
        float m = j.mA + j.mB;
        float k11 = m + iA * j.rAy * j.rAy + iB * j.rBy * j.rBy;
        float k12 = -iA * j.rAy * j.rAx - iB * j.rBy * j.rBx;
        float k22 = m + iA * j.rAx * j.rAx + iB * j.rBx * j.rBx;
        // The anchors' relative velocity change per unit torque.
        float gx = -iA * j.rAy - iB * j.rBy;
        float gy = iA * j.rAx + iB * j.rBx;
        float det = k11 * k22 - k12 * k12;
        if (!(det > 0f)) {
            projected = false;
            setInverseMass(iA + iB);
            return;
        }
        float inv = 1f / det;
        lx = -inv * (k22 * gx - k12 * gy);
        ly = -inv * (k11 * gy - k12 * gx);
        projected = true;
        setInverseMass(iA + iB + lx * gx + ly * gy);
    }

    @Override
    float velocity(SolverStep step) {
        float w = step.getAngularVelocity(joint.ib) - step.getAngularVelocity(joint.ia);
        if (projected) {
            w += lx * joint.relativeVelocityX(step) + ly * joint.relativeVelocityY(step);
        }
        return w;
    }

    @Override
    void apply(SolverStep step, float impulse) {
        step.applyAngularImpulse(joint.ia, -impulse);
        step.applyAngularImpulse(joint.ib, impulse);
        if (projected) {
            joint.applyLinear(step, lx * impulse, ly * impulse);
            tickLinearX += lx * impulse;
            tickLinearY += ly * impulse;
        }
    }
}
