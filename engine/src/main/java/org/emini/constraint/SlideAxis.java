package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * The geometry of an axis fixed in body A through A's anchor, along which B's anchor slides
 * (prismatic and wheel joints): the axis and its normal as A has turned since the tick began, B's
 * anchor's position along and across it, and the lever arms of both directions. A's arm runs from
 * its centre to B's anchor, so that A's turning moves the line under B's anchor.
 */
final class SlideAxis {
    private final float localX;
    private final float localY;
    private float axis0X;
    private float axis0Y;

    // Set by update(): the axis u, its left normal n = (−u.y, u.x), positions along and across.
    float ux;
    float uy;
    float nx;
    float ny;
    float translation;
    float offset;
    /** (A's arm) × u and (B's arm) × u. */
    float a1;
    float a2;
    /** (A's arm) × n and (B's arm) × n. */
    float s1;
    float s2;

    /**
     * @param where the constructor, for messages
     * @param x the axis's x in A's frame (any length but 0)
     * @param y the axis's y in A's frame
     */
    SlideAxis(String where, float x, float y) {
        Check.finite(where, "axis x", x);
        Check.finite(where, "axis y", y);
        float len = EMath.sqrt(x * x + y * y);
        if (!(len > 0f)) {
            throw new IllegalArgumentException(where + ": the axis (" + x + ", " + y + ") has no direction");
        }
        localX = x / len;
        localY = y / len;
    }

    float getLocalX() {
        return localX;
    }

    float getLocalY() {
        return localY;
    }

    /** A world direction in body A's frame, for joints made from world coordinates. */
    static float localX(Body a, float x, float y) {
        return a.getCos() * x + a.getSin() * y;
    }

    /** See {@link #localX}. */
    static float localY(Body a, float x, float y) {
        return -a.getSin() * x + a.getCos() * y;
    }

    /** B's anchor's position along the axis from A's anchor, where the bodies are now (outside the solve). */
    float translation(TwoBodyConstraint j) {
        Body a = j.bodyA;
        float ux = a.getCos() * localX - a.getSin() * localY;
        float uy = a.getSin() * localX + a.getCos() * localY;
        return ux * (j.getAnchorBX() - j.getAnchorAX()) + uy * (j.getAnchorBY() - j.getAnchorAY());
    }

    /** The axis at the tick's start, from A's rotation then, and the geometry there. */
    void begin(SolverStep step, TwoBodyConstraint j) {
        Body a = j.bodyA;
        axis0X = a.getCos() * localX - a.getSin() * localY;
        axis0Y = a.getSin() * localX + a.getCos() * localY;
        now(step, j);
    }

    /** The joint's arms and the axis's geometry now. */
    void now(SolverStep step, TwoBodyConstraint j) {
        j.arms(step);
        update(step, j);
    }

    /** Applies an impulse across the axis (B's anchor pushed along n), plus an angular impulse on both (B +, A −). */
    void applyNormal(SolverStep step, TwoBodyConstraint j, float impulse, float angular) {
        j.applyLever(step, impulse * nx, impulse * ny, impulse * s1 + angular, impulse * s2 + angular);
    }

    /** The geometry now; the joint's arms() must have run this pass. */
    private void update(SolverStep step, TwoBodyConstraint j) {
        float c = step.getDeltaCos(j.ia);
        float s = step.getDeltaSin(j.ia);
        ux = c * axis0X - s * axis0Y;
        uy = s * axis0X + c * axis0Y;
        nx = -uy;
        ny = ux;
        float dx = j.sepX;
        float dy = j.sepY;
        translation = ux * dx + uy * dy;
        offset = nx * dx + ny * dy;
        float armX = dx + j.rAx;
        float armY = dy + j.rAy;
        a1 = armX * uy - armY * ux;
        a2 = j.rBx * uy - j.rBy * ux;
        s1 = armX * ny - armY * nx;
        s2 = j.rBx * ny - j.rBy * nx;
    }

    /** The rate B's anchor moves across the axis, relative to the line. */
    float normalVelocity(SolverStep step, TwoBodyConstraint j) {
        int ia = j.ia;
        int ib = j.ib;
        return nx * (step.getVelocityX(ib) - step.getVelocityX(ia)) + ny * (step.getVelocityY(ib) - step.getVelocityY(ia))
            + s2 * step.getAngularVelocity(ib) - s1 * step.getAngularVelocity(ia);
    }
}
