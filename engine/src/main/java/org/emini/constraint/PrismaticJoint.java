package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * A slide: B's anchor moves only along an axis fixed in body A through A's anchor, and the bodies
 * keep their relative angle. With translation limits, a motor (speed, capped force, its reaction
 * on A) and a spring toward translation 0. Box2D's {@code PrismaticJoint}; pymunk has no single
 * equivalent (a GrooveJoint with a gear-like angle lock).
 *
 * <p>The translation is B's anchor's position along the axis, measured from A's anchor (0 when
 * the joint is made with the anchors together). The point-on-line and angle rows are solved
 * together as one 2×2 block after the axis's rows (spring, motor, limits), as Box2D v3 does; their
 * position error is corrected with the world's joint softness.
 *
 * <p>Example, a lift that rises at 40 px/s with at most 5,000 mass·px/s² and stops 300 px up:
 * <pre>{@code
 * PrismaticJoint lift = PrismaticJoint.atWorldPoint(ground, cabin, x, y, 0f, -1f);
 * lift.setLimits(0f, 300f);
 * lift.setMotor(40f, 5000f);
 * world.addConstraint(lift);
 * }</pre>
 */
public final class PrismaticJoint extends TwoBodyConstraint {
    private final SlideAxis slide;
    private final LinearAxis axis = new LinearAxis(this);
    private final float referenceAngle;
    private boolean active;
    // Impulses of the current substep across the axis and on the angle, their warm starts, the tick's sums.
    private float perpImpulse;
    private float angleImpulse;
    private float warmPerp;
    private float warmAngle;
    private float tickPerp;
    private float tickAngle;
    private float torque;

    /**
     * Creates a slide between two bodies in the same world.
     *
     * @param a the body that carries the axis
     * @param b the body that slides
     * @param ax x of A's anchor, a point of the axis, in a's own frame (px)
     * @param ay y of A's anchor in a's own frame (px)
     * @param bx x of B's anchor in b's own frame (px)
     * @param by y of B's anchor in b's own frame (px)
     * @param axisX the axis's x in a's own frame (any length but 0)
     * @param axisY the axis's y in a's own frame
     */
    public PrismaticJoint(Body a, Body b, float ax, float ay, float bx, float by, float axisX, float axisY) {
        super("PrismaticJoint", a, b, ax, ay, bx, by);
        slide = new SlideAxis("PrismaticJoint", axisX, axisY);
        referenceAngle = b.getAngle() - a.getAngle();
    }

    /**
     * Creates a slide through a world point where both bodies are now, along a world direction.
     *
     * @param a the body that carries the axis
     * @param b the body that slides
     * @param x the point's world x (px)
     * @param y the point's world y (px)
     * @param axisX the axis's world x (any length but 0)
     * @param axisY the axis's world y
     * @return the joint (not yet added to the world)
     */
    public static PrismaticJoint atWorldPoint(Body a, Body b, float x, float y, float axisX, float axisY) {
        String where = "PrismaticJoint.atWorldPoint";
        Check.finite(where, "x", x);
        Check.finite(where, "y", y);
        Require.inWorld(where, "body a", a);
        Require.inWorld(where, "body b", b);
        Check.finite(where, "axis x", axisX);
        Check.finite(where, "axis y", axisY);
        return new PrismaticJoint(a, b, a.toLocalX(x, y), a.toLocalY(x, y), b.toLocalX(x, y), b.toLocalY(x, y),
            SlideAxis.localX(a, axisX, axisY), SlideAxis.localY(a, axisX, axisY));
    }

    /**
     * The axis's x in A's frame, of unit length.
     *
     * @return x
     */
    public float getLocalAxisX() {
        return slide.getLocalX();
    }

    /**
     * The axis's y in A's frame, of unit length.
     *
     * @return y
     */
    public float getLocalAxisY() {
        return slide.getLocalY();
    }

    /**
     * B's anchor's position along the axis from A's anchor, where the bodies are now.
     *
     * @return the translation (px)
     */
    public float getTranslation() {
        return slide.translation(this);
    }

    /**
     * Keeps the translation within [lower, upper].
     *
     * @param lower the lower limit (px)
     * @param upper the upper limit (px), &ge; lower
     */
    public void setLimits(float lower, float upper) {
        axis.setLimits("PrismaticJoint.setLimits", lower, upper);
    }

    /** Lets the joint slide freely again. */
    public void disableLimits() {
        axis.disableLimits();
    }

    /**
     * Whether the translation is limited.
     *
     * @return true after {@link #setLimits}
     */
    public boolean isLimitEnabled() {
        return axis.isLimitEnabled();
    }

    /**
     * The lower translation limit.
     *
     * @return the limit (px)
     */
    public float getLowerLimit() {
        return axis.getLower();
    }

    /**
     * The upper translation limit.
     *
     * @return the limit (px)
     */
    public float getUpperLimit() {
        return axis.getUpper();
    }

    /**
     * Drives the sliding speed (B's anchor relative to A along the axis) with a capped force, its
     * reaction on A.
     *
     * @param speed the target speed (px/s)
     * @param maxForce the largest force (mass·px/s²), &ge; 0; Float.POSITIVE_INFINITY for no limit
     */
    public void setMotor(float speed, float maxForce) {
        axis.setMotor("PrismaticJoint.setMotor", speed, maxForce);
    }

    /** Switches the motor off. */
    public void disableMotor() {
        axis.disableMotor();
    }

    /**
     * Whether the motor is on.
     *
     * @return true after {@link #setMotor}
     */
    public boolean isMotorEnabled() {
        return axis.isMotorEnabled();
    }

    /**
     * The motor's target speed.
     *
     * @return the speed (px/s)
     */
    public float getMotorSpeed() {
        return axis.getMotorSpeed();
    }

    /**
     * The motor's force cap.
     *
     * @return the largest force (mass·px/s²)
     */
    public float getMaxMotorForce() {
        return axis.getMaxMotorForce();
    }

    /**
     * The force the motor exerted on B along the axis in the last tick, averaged over it.
     *
     * @return the signed force (mass·px/s²)
     */
    public float getMotorForce() {
        return axis.getMotorForce();
    }

    /**
     * A spring along the axis toward translation 0, soft: its frequency and damping ratio hold
     * whatever the masses, and it is stable at any frequency.
     *
     * @param hertz the natural frequency (Hz), &ge; 0; 0 exerts nothing
     * @param dampingRatio the damping ratio, &ge; 0 (1 is critical)
     */
    public void setSpring(float hertz, float dampingRatio) {
        axis.setSpring("PrismaticJoint.setSpring", hertz, dampingRatio);
    }

    /** Removes the spring. */
    public void disableSpring() {
        axis.disableSpring();
    }

    /**
     * The spring's frequency.
     *
     * @return the natural frequency (Hz); 0 without a spring
     */
    public float getSpringHertz() {
        return axis.isSpringEnabled() ? axis.getSpringHertz() : 0f;
    }

    /**
     * The spring's damping ratio.
     *
     * @return the damping ratio
     */
    public float getSpringDampingRatio() {
        return axis.getSpringDampingRatio();
    }

    /**
     * The force of the spring, motor and limits together on B along the axis in the last tick.
     *
     * @return the signed force (mass·px/s²); positive pushes B along the axis
     */
    public float getAxialForce() {
        return axis.getForce();
    }

    /**
     * The torque that kept the bodies' relative angle in the last tick.
     *
     * @return the magnitude (mass·px²/s²)
     */
    public float getTorque() {
        return torque;
    }

    @Override
    public void prepare(SolverStep step) {
        active = prepareAnchors(step);
        slide.begin(step, this);
        axis.prepare(axis.follow(slide), 1f, step);
        tickPerp = 0f;
        tickAngle = 0f;
    }

    @Override
    public void warmStart(SolverStep step) {
        if (!active) {
            return;
        }
        float scale = substepScale(step);
        perpImpulse *= scale;
        angleImpulse *= scale;
        warmPerp = perpImpulse;
        warmAngle = angleImpulse;
        tickPerp += perpImpulse;
        tickAngle += angleImpulse;
        slide.now(step, this);
        if (axis.isActive()) {
            axis.follow(slide);
            axis.warmStart(step, scale);
        }
        slide.applyNormal(step, this, perpImpulse, angleImpulse);
    }

    @Override
    public float solve(SolverStep step, boolean useBias) {
        if (!active) {
            return 0f;
        }
        SlideAxis g = slide;
        g.now(step, this);
        float change = 0f;
        if (axis.isActive()) {
            axis.follow(g);
            change = axis.solve(step, useBias, g.translation);
        }
        float cx = g.normalVelocity(step, this);
        float cw = step.getAngularVelocity(ib) - step.getAngularVelocity(ia);
        float massScale = 1f;
        float impulseScale = 0f;
        if (useBias) {
            float rate = step.getJointBiasRate();
            cx += pushBias(step, rate, g.offset);
            cw += turnBias(step, rate, step.getAngle(bodyB) - step.getAngle(bodyA) - referenceAngle);
            massScale = step.getJointMassScale();
            impulseScale = step.getJointImpulseScale();
        }
        float k11 = mA + mB + iA * g.s1 * g.s1 + iB * g.s2 * g.s2;
        float k12 = iA * g.s1 + iB * g.s2;
        float k22 = iA + iB;
        if (k22 == 0f) {
            // Neither body turns: the angle row is idle, and the block stays invertible.
            k22 = 1f;
        }
        float det = k11 * k22 - k12 * k12;
        if (!(det > 0f)) {
            return change;
        }
        float inv = massScale / det;
        float ip = -inv * (k22 * cx - k12 * cw) - impulseScale * perpImpulse;
        float iw = -inv * (k11 * cw - k12 * cx) - impulseScale * angleImpulse;
        perpImpulse += ip;
        angleImpulse += iw;
        tickPerp += ip;
        tickAngle += iw;
        g.applyNormal(step, this, ip, iw);
        if (useBias) {
            return 0f;
        }
        float jp = perpImpulse - warmPerp;
        float jw = angleImpulse - warmAngle;
        return Math.max(change, Math.max(Math.abs(k11 * jp + k12 * jw), Math.abs(k12 * jp + k22 * jw) * radius));
    }

    @Override
    public void finish(SolverStep step) {
        float dt = step.getTimestep();
        axis.finish(dt);
        float perp = tickPerp / dt;
        float along = axis.getForce();
        force = EMath.length(perp, along);
        torque = Math.abs(tickAngle) / dt;
    }

    @Override
    public String toString() {
        return "PrismaticJoint(" + bodyA + ", " + bodyB + ")";
    }
}
