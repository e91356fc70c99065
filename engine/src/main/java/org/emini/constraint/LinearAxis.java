package org.emini.constraint;

import org.emini.dynamics.SolverStep;

/**
 * Rows along a direction between a joint's anchors: a slide axis, or the anchor line. The joint
 * sets the direction and the lever arms for each pass ({@link #set}); the impulse pushes B's
 * anchor along the direction and A's against it.
 */
final class LinearAxis extends AxisRows {
    private final TwoBodyConstraint joint;
    // The unit direction, and the arms' cross products with it: A's from its centre to B's anchor
    // (so that A's turning moves the axis), B's from its centre to its anchor.
    private float ux;
    private float uy;
    private float a1;
    private float a2;

    LinearAxis(TwoBodyConstraint joint) {
        this.joint = joint;
    }

    /**
     * Sets the direction and arms, and returns the inverse effective mass along it.
     *
     * @param dirX the unit direction's x
     * @param dirY the unit direction's y
     * @param crossA (arm on A) × direction
     * @param crossB (arm on B) × direction
     * @return J·M⁻¹·Jᵀ
     */
    float set(float dirX, float dirY, float crossA, float crossB) {
        ux = dirX;
        uy = dirY;
        a1 = crossA;
        a2 = crossB;
        TwoBodyConstraint j = joint;
        return j.mA + j.mB + j.iA * a1 * a1 + j.iB * a2 * a2;
    }

    /** Points the rows along a slide axis as it is now, with its effective mass. */
    float follow(SlideAxis g) {
        float k = set(g.ux, g.uy, g.a1, g.a2);
        setInverseMass(k);
        return k;
    }

    @Override
    float velocity(SolverStep step) {
        int ia = joint.ia;
        int ib = joint.ib;
        return ux * (step.getVelocityX(ib) - step.getVelocityX(ia)) + uy * (step.getVelocityY(ib) - step.getVelocityY(ia))
            + a2 * step.getAngularVelocity(ib) - a1 * step.getAngularVelocity(ia);
    }

    @Override
    void apply(SolverStep step, float impulse) {
        joint.applyLever(step, ux * impulse, uy * impulse, a1 * impulse, a2 * impulse);
    }
}
