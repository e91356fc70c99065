package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * A hinge: a loose pin joint (the bodies' anchors held together, free to turn) with what games
 * expect of a hinge: lower and upper angle limits, a motor between the two bodies and a
 * rotational spring. Box2D's and JBox2D's {@code RevoluteJoint}, pymunk's PivotJoint with a
 * RotaryLimitJoint, SimpleMotor and DampedRotarySpring.
 *
 * <p>A class of its own rather than setters on {@link Joint}: the manual's pin joint keeps its API
 * and its results bit for bit, and the hinge is a loose {@code Joint} (the same solve, held
 * inside) plus rows on the joint angle, θ = (B's angle − A's angle) − the reference angle, the
 * relative angle when the joint is made. The angle counts whole turns (it is not wrapped), so
 * limits may span more than one turn. Rows are solved before the pin, in Box2D v3's order: the
 * spring (soft, its own frequency), the motor (capped torque, the reaction on A), then the limits
 * (rigid, with the world's joint softness for their position error). The rows act on the
 * rotation about the pin (each torque comes with the linear impulse at the pivot that leaves the
 * pin's velocity unchanged), so a small bob on a long arm stops at its limit instead of turning
 * about its own centre against the pin.
 *
 * <p>Example, a knee that bends 0 to 150° backwards:
 * <pre>{@code
 * RevoluteJoint knee = RevoluteJoint.atWorldPoint(thigh, shin, x, y);
 * knee.setLimits(-2.6f, 0f);
 * knee.setCollisionLayer(3);
 * world.addConstraint(knee);
 * }</pre>
 */
public final class RevoluteJoint extends TwoBodyConstraint {
    private final Joint pin;
    private final AngularAxis axis = new AngularAxis(this);
    private final float referenceAngle;
    private boolean active;

    /**
     * Creates a hinge between two bodies in the same world; its reference angle is their relative
     * angle now.
     *
     * @param a the first body
     * @param b the second body
     * @param ax x of the pivot in a's own frame (px)
     * @param ay y of the pivot in a's own frame (px)
     * @param bx x of the pivot in b's own frame (px)
     * @param by y of the pivot in b's own frame (px)
     */
    public RevoluteJoint(Body a, Body b, float ax, float ay, float bx, float by) {
        super("RevoluteJoint", a, b, ax, ay, bx, by);
        pin = new Joint(a, b, ax, ay, bx, by, false);
        referenceAngle = b.getAngle() - a.getAngle();
    }

    /**
     * Creates a hinge whose pivot is a world point, where both bodies are now.
     *
     * @param a the first body
     * @param b the second body
     * @param x the pivot's world x (px)
     * @param y the pivot's world y (px)
     * @return the joint (not yet added to the world)
     */
    public static RevoluteJoint atWorldPoint(Body a, Body b, float x, float y) {
        Check.finite("RevoluteJoint.atWorldPoint", "x", x);
        Check.finite("RevoluteJoint.atWorldPoint", "y", y);
        Require.inWorld("RevoluteJoint.atWorldPoint", "body a", a);
        Require.inWorld("RevoluteJoint.atWorldPoint", "body b", b);
        return new RevoluteJoint(a, b, a.toLocalX(x, y), a.toLocalY(x, y), b.toLocalX(x, y), b.toLocalY(x, y));
    }

    /**
     * The relative angle at creation, from which {@link #getJointAngle()} counts.
     *
     * @return B's angle minus A's then (rad)
     */
    public float getReferenceAngle() {
        return referenceAngle;
    }

    /**
     * The joint angle now: B's angle minus A's, minus the reference angle.
     *
     * @return θ (rad), positive when B has turned the way angles grow relative to A
     */
    public float getJointAngle() {
        return bodyB.getAngle() - bodyA.getAngle() - referenceAngle;
    }

    /**
     * Keeps the joint angle within [lower, upper].
     *
     * @param lower the lower limit (rad)
     * @param upper the upper limit (rad), &ge; lower
     */
    public void setLimits(float lower, float upper) {
        axis.setLimits("RevoluteJoint.setLimits", lower, upper);
    }

    /** Lets the joint turn freely again. */
    public void disableLimits() {
        axis.disableLimits();
    }

    /**
     * Whether the angle is limited.
     *
     * @return true after {@link #setLimits}
     */
    public boolean isLimitEnabled() {
        return axis.isLimitEnabled();
    }

    /**
     * The lower angle limit.
     *
     * @return the limit (rad)
     */
    public float getLowerLimit() {
        return axis.getLower();
    }

    /**
     * The upper angle limit.
     *
     * @return the limit (rad)
     */
    public float getUpperLimit() {
        return axis.getUpper();
    }

    /**
     * Drives the joint's angular speed (B's relative to A's) with a capped torque, its reaction
     * on A.
     *
     * @param speed the target dθ/dt (rad/s)
     * @param maxTorque the largest torque (mass·px²/s²), &ge; 0; Float.POSITIVE_INFINITY for no limit
     */
    public void setMotor(float speed, float maxTorque) {
        axis.setMotor("RevoluteJoint.setMotor", speed, maxTorque);
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
     * @return dθ/dt (rad/s)
     */
    public float getMotorSpeed() {
        return axis.getMotorSpeed();
    }

    /**
     * The motor's torque cap.
     *
     * @return the torque (mass·px²/s²)
     */
    public float getMaxMotorTorque() {
        return axis.getMaxMotorForce();
    }

    /**
     * The torque the motor exerted on B in the last tick, averaged over it (A took the opposite).
     *
     * @return the signed torque (mass·px²/s²)
     */
    public float getMotorTorque() {
        return axis.getMotorForce();
    }

    /**
     * A rotational spring toward the reference angle (θ = 0), soft: its natural frequency and
     * damping ratio hold whatever the bodies' inertias, and it is stable at any frequency.
     *
     * @param hertz the natural frequency (Hz), &ge; 0; 0 exerts nothing
     * @param dampingRatio the damping ratio, &ge; 0 (1 is critical)
     */
    public void setSpring(float hertz, float dampingRatio) {
        axis.setSpring("RevoluteJoint.setSpring", hertz, dampingRatio);
    }

    /** Removes the rotational spring. */
    public void disableSpring() {
        axis.disableSpring();
    }

    /**
     * The rotational spring's frequency.
     *
     * @return the frequency (Hz), 0 without a spring
     */
    public float getSpringHertz() {
        return axis.isSpringEnabled() ? axis.getSpringHertz() : 0f;
    }

    /**
     * The rotational spring's damping ratio.
     *
     * @return ζ
     */
    public float getSpringDampingRatio() {
        return axis.getSpringDampingRatio();
    }

    /**
     * The torque of the spring, motor and limits together on B in the last tick, averaged over it.
     *
     * @return the signed torque (mass·px²/s²); positive turns B the way angles grow
     */
    public float getTorque() {
        return axis.getForce();
    }

    @Override
    public void prepare(SolverStep step) {
        active = prepareAnchors(step);
        pin.prepare(step);
        axis.prepare(step);
    }

    @Override
    public void warmStart(SolverStep step) {
        if (!active) {
            return;
        }
        float scale = substepScale(step);
        if (axis.isActive()) {
            arms(step);
            axis.projectOffPin();
            axis.warmStart(step, scale);
        }
        pin.warmStart(step);
    }

    @Override
    public float solve(SolverStep step, boolean useBias) {
        if (!active) {
            return 0f;
        }
        float change = 0f;
        if (axis.isActive()) {
            arms(step);
            axis.projectOffPin();
            float angle = step.getAngle(bodyB) - step.getAngle(bodyA) - referenceAngle;
            change = axis.solve(step, useBias, angle);
        }
        return Math.max(change, pin.solve(step, useBias));
    }

    @Override
    public void finish(SolverStep step) {
        pin.finish(step);
        axis.finish(step.getTimestep());
        // The pin's load and the linear part of the projected rows' impulses act at the same anchors.
        float inv = 1f / step.getTimestep();
        float x = pin.getTickImpulseX() + axis.tickLinearX;
        float y = pin.getTickImpulseY() + axis.tickLinearY;
        force = EMath.length(x * inv, y * inv);
    }

    @Override
    public String toString() {
        return "RevoluteJoint(" + bodyA + ", " + bodyB + ")";
    }
}
