package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * A car's wheel: the wheel's centre (B's anchor) stays on a suspension axis fixed in the chassis
 * (A) through A's anchor, sprung along it toward translation 0, and the wheel turns freely, or
 * driven by a motor between wheel and chassis. Box2D's {@code WheelJoint}; in pymunk a
 * GrooveJoint with a DampedSpring and a SimpleMotor.
 *
 * <p>The suspension is a soft constraint of the given frequency and damping ratio (stable at any
 * frequency); with the wheel held, a chassis of mass m bounces with period 1/hertz and sags
 * g/(2π·hertz)² under its weight (the spring's stiffness is m·(2π·hertz)² for the effective mass
 * m along the axis). Optional limits bound the travel. The point-on-line row is rigid, with the
 * world's joint softness for its position error.
 *
 * <p>Example, a rear wheel 30 px below the chassis, sprung at 4 Hz, driven at 10 rad/s:
 * <pre>{@code
 * WheelJoint rear = WheelJoint.atWorldPoint(chassis, wheel, wheel.getX(), wheel.getY(), 0f, 1f);
 * rear.setSpring(4f, 0.7f);
 * rear.setMotor(10f, 400000f);
 * world.addConstraint(rear);
 * }</pre>
 */
public final class WheelJoint extends TwoBodyConstraint {
    private final SlideAxis slide;
    private final LinearAxis suspension = new LinearAxis(this);
    private final AngularAxis drive = new AngularAxis(this);
    private boolean active;
    private float perpImpulse;
    private float warmPerp;
    private float tickPerp;

    /**
     * Creates a wheel joint, the suspension without a spring (the wheel slides freely along the
     * axis until {@link #setSpring} or {@link #setLimits}).
     *
     * @param a the chassis, which carries the axis
     * @param b the wheel
     * @param ax x of A's anchor, a point of the axis, in a's own frame (px)
     * @param ay y of A's anchor in a's own frame (px)
     * @param bx x of B's anchor (usually its centre, 0) in b's own frame (px)
     * @param by y of B's anchor in b's own frame (px)
     * @param axisX the suspension axis's x in a's own frame (any length but 0)
     * @param axisY the suspension axis's y in a's own frame
     */
    public WheelJoint(Body a, Body b, float ax, float ay, float bx, float by, float axisX, float axisY) {
        super("WheelJoint", a, b, ax, ay, bx, by);
        slide = new SlideAxis("WheelJoint", axisX, axisY);
    }

    /**
     * Creates a wheel joint through a world point where both bodies are now (usually the wheel's
     * centre), along a world direction.
     *
     * @param a the chassis
     * @param b the wheel
     * @param x the point's world x (px)
     * @param y the point's world y (px)
     * @param axisX the axis's world x (any length but 0)
     * @param axisY the axis's world y
     * @return the joint (not yet added to the world)
     */
    public static WheelJoint atWorldPoint(Body a, Body b, float x, float y, float axisX, float axisY) {
        String where = "WheelJoint.atWorldPoint";
        Check.finite(where, "x", x);
        Check.finite(where, "y", y);
        Require.inWorld(where, "body a", a);
        Require.inWorld(where, "body b", b);
        Check.finite(where, "axis x", axisX);
        Check.finite(where, "axis y", axisY);
        return new WheelJoint(a, b, a.toLocalX(x, y), a.toLocalY(x, y), b.toLocalX(x, y), b.toLocalY(x, y),
            SlideAxis.localX(a, axisX, axisY), SlideAxis.localY(a, axisX, axisY));
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
     * Springs the suspension toward translation 0.
     *
     * @param hertz the natural frequency (Hz), &ge; 0; 0 exerts nothing
     * @param dampingRatio the damping ratio, &ge; 0 (1 is critical)
     */
    public void setSpring(float hertz, float dampingRatio) {
        suspension.setSpring("WheelJoint.setSpring", hertz, dampingRatio);
    }

    /**
     * The suspension's frequency.
     *
     * @return the frequency (Hz), 0 without a spring
     */
    public float getSpringHertz() {
        return suspension.isSpringEnabled() ? suspension.getSpringHertz() : 0f;
    }

    /**
     * The suspension's damping ratio.
     *
     * @return ζ
     */
    public float getSpringDampingRatio() {
        return suspension.getSpringDampingRatio();
    }

    /**
     * Bounds the suspension's travel.
     *
     * @param lower the lower limit of the translation (px)
     * @param upper the upper limit (px), &ge; lower
     */
    public void setLimits(float lower, float upper) {
        suspension.setLimits("WheelJoint.setLimits", lower, upper);
    }

    /** Removes the travel limits. */
    public void disableLimits() {
        suspension.disableLimits();
    }

    /**
     * Drives the wheel's angular speed relative to the chassis with a capped torque, its reaction
     * on the chassis.
     *
     * @param speed the target speed (rad/s), positive turns the way angles grow
     * @param maxTorque the largest torque (mass·px²/s²), &ge; 0; Float.POSITIVE_INFINITY for no limit
     */
    public void setMotor(float speed, float maxTorque) {
        drive.setMotor("WheelJoint.setMotor", speed, maxTorque);
    }

    /** Lets the wheel turn freely. */
    public void disableMotor() {
        drive.disableMotor();
    }

    /**
     * The motor's target speed.
     *
     * @return the speed (rad/s)
     */
    public float getMotorSpeed() {
        return drive.getMotorSpeed();
    }

    /**
     * Whether the motor is on.
     *
     * @return true after {@link #setMotor}
     */
    public boolean isMotorEnabled() {
        return drive.isMotorEnabled();
    }

    /**
     * The motor's torque cap.
     *
     * @return the largest torque (mass·px²/s²)
     */
    public float getMaxMotorTorque() {
        return drive.getMaxMotorForce();
    }

    /**
     * Whether the suspension's travel is limited.
     *
     * @return true after {@link #setLimits}
     */
    public boolean isLimitEnabled() {
        return suspension.isLimitEnabled();
    }

    /**
     * The lower travel limit.
     *
     * @return the limit (px)
     */
    public float getLowerLimit() {
        return suspension.getLower();
    }

    /**
     * The upper travel limit.
     *
     * @return the limit (px)
     */
    public float getUpperLimit() {
        return suspension.getUpper();
    }

    /**
     * The torque the motor exerted on the wheel in the last tick, averaged over it.
     *
     * @return the signed torque (mass·px²/s²)
     */
    public float getMotorTorque() {
        return drive.getMotorForce();
    }

    /**
     * The suspension's force on the wheel along the axis in the last tick (spring and limits).
     *
     * @return the signed force (mass·px/s²)
     */
    public float getSpringForce() {
        return suspension.getForce();
    }

    @Override
    public void prepare(SolverStep step) {
        active = prepareAnchors(step);
        slide.begin(step, this);
        suspension.prepare(suspension.follow(slide), 1f, step);
        drive.prepare(step);
        tickPerp = 0f;
    }

    @Override
    public void warmStart(SolverStep step) {
        if (!active) {
            return;
        }
        float scale = substepScale(step);
        perpImpulse *= scale;
        warmPerp = perpImpulse;
        tickPerp += perpImpulse;
        slide.now(step, this);
        if (drive.isActive()) {
            drive.warmStart(step, scale);
        }
        if (suspension.isActive()) {
            suspension.follow(slide);
            suspension.warmStart(step, scale);
        }
        slide.applyNormal(step, this, perpImpulse, 0f);
    }

    @Override
    public float solve(SolverStep step, boolean useBias) {
        if (!active) {
            return 0f;
        }
        float change = 0f;
        if (drive.isActive()) {
            change = drive.solve(step, useBias, 0f);
        }
        SlideAxis g = slide;
        g.now(step, this);
        if (suspension.isActive()) {
            suspension.follow(g);
            change = Math.max(change, suspension.solve(step, useBias, g.translation));
        }
        float k = mA + mB + iA * g.s1 * g.s1 + iB * g.s2 * g.s2;
        if (!(k > 0f)) {
            return change;
        }
        float cdot = g.normalVelocity(step, this);
        float massScale = 1f;
        float impulseScale = 0f;
        if (useBias) {
            cdot += pushBias(step, step.getJointBiasRate(), g.offset);
            massScale = step.getJointMassScale();
            impulseScale = step.getJointImpulseScale();
        }
        float impulse = -massScale * cdot / k - impulseScale * perpImpulse;
        perpImpulse += impulse;
        tickPerp += impulse;
        g.applyNormal(step, this, impulse, 0f);
        return useBias ? change : Math.max(change, Math.abs((perpImpulse - warmPerp) * k));
    }

    @Override
    public void finish(SolverStep step) {
        float dt = step.getTimestep();
        suspension.finish(dt);
        drive.finish(dt);
        force = EMath.length(tickPerp / dt, suspension.getForce());
    }

    @Override
    public String toString() {
        return "WheelJoint(" + bodyA + ", " + bodyB + ")";
    }
}
