package org.emini.constraint;

import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;

/**
 * The scalar rows a joint may put on its one free degree of freedom (an angle, a slide, a length):
 * a soft spring toward a rest position, a motor with a capped force, a lower and an upper limit,
 * or a rigid lock. Solved as Box2D v3 solves its joints' axes: the spring with its own softness in
 * both passes, the motor without bias, the limits as one-sided rows that look ahead (a gap that the
 * substep would close is closed, not crossed) and correct penetration with the world's joint
 * softness in the biased pass only.
 *
 * <p>The joint says what the axis is: {@link #velocity} is the rate the position grows at,
 * {@link #apply} applies an impulse that grows it. Impulses are per substep, as the joints' are.
 * Nothing here allocates after construction.
 */
abstract class AxisRows {
    // Settings.
    private boolean springOn;
    private float hertz;
    private float dampingRatio;
    private float springTarget;
    private boolean motorOn;
    private float motorSpeed;
    private float maxMotorForce;
    private boolean limitOn;
    private float lower;
    private float upper;
    private boolean locked;
    private float lockTarget;

    // Per tick: the effective mass along the axis, its inverse, and rim radius (for angular axes).
    private float mass;
    private float invMass;
    private float scale = 1f;
    private final float[] soft = new float[3];

    // Impulses of the current substep, what it warm-started with, and the tick's sums.
    private float springImpulse;
    private float motorImpulse;
    private float lowerImpulse;
    private float upperImpulse;
    private float lockImpulse;
    private float warm;
    private float tickTotal;
    private float tickMotor;
    private float force;
    private float motorForce;

    /**
     * The rate the position grows at, from the bodies' current velocities.
     *
     * @param step the tick's solver state
     * @return d(position)/dt
     */
    abstract float velocity(SolverStep step);

    /**
     * Applies an impulse that grows the position, with its reaction on the other body.
     *
     * @param step the tick's solver state
     * @param impulse the impulse (mass·px/s, or mass·px²/s for an angle)
     */
    abstract void apply(SolverStep step, float impulse);

    boolean isActive() {
        return springOn || motorOn || limitOn || locked;
    }

    void setSpring(String where, float springHertz, float ratio) {
        hertz = Check.nonNegative(where, "hertz", springHertz);
        dampingRatio = Check.nonNegative(where, "dampingRatio", ratio);
        springOn = true;
    }

    void setSpringTarget(String where, float target) {
        springTarget = Check.finite(where, "target", target);
    }

    void disableSpring() {
        springOn = false;
        springImpulse = 0f;
    }

    void setMotor(String where, float speed, float maxForce) {
        motorSpeed = Check.finite(where, "speed", speed);
        maxMotorForce = Check.limit(where, "max", maxForce);
        motorOn = true;
    }

    void disableMotor() {
        motorOn = false;
        motorImpulse = 0f;
    }

    void setLimits(String where, float lowerLimit, float upperLimit) {
        Check.finite(where, "lower", lowerLimit);
        Check.finite(where, "upper", upperLimit);
        if (lowerLimit > upperLimit) {
            throw new IllegalArgumentException(where + ": lower (" + lowerLimit + ") must not exceed upper ("
                + upperLimit + ")");
        }
        lower = lowerLimit;
        upper = upperLimit;
        limitOn = true;
    }

    void disableLimits() {
        limitOn = false;
        lowerImpulse = 0f;
        upperImpulse = 0f;
    }

    /** Holds the position at a target, rigidly (the world's joint softness), instead of any other row. */
    void lock(float target) {
        locked = true;
        lockTarget = target;
    }

    void unlock() {
        locked = false;
        lockImpulse = 0f;
    }

    boolean isSpringEnabled() {
        return springOn;
    }

    float getSpringHertz() {
        return hertz;
    }

    float getSpringDampingRatio() {
        return dampingRatio;
    }

    float getSpringTarget() {
        return springTarget;
    }

    boolean isMotorEnabled() {
        return motorOn;
    }

    float getMotorSpeed() {
        return motorSpeed;
    }

    float getMaxMotorForce() {
        return maxMotorForce;
    }

    boolean isLimitEnabled() {
        return limitOn;
    }

    float getLower() {
        return lower;
    }

    float getUpper() {
        return upper;
    }

    /** The axis's whole force (or torque) in the last tick, signed: positive grows the position. */
    float getForce() {
        return force;
    }

    /** The motor's force (or torque) in the last tick, signed. */
    float getMotorForce() {
        return motorForce;
    }

    /**
     * Starts a tick.
     *
     * @param inverseMass the inverse effective mass along the axis, J·M⁻¹·Jᵀ
     * @param rim the length that turns the axis's velocity into a speed (1 for slides, the bodies'
     *     rim radius for angles), for the relax pass's report
     * @param step the tick's solver state
     */
    void prepare(float inverseMass, float rim, SolverStep step) {
        invMass = inverseMass;
        mass = inverseMass > 0f ? 1f / inverseMass : 0f;
        scale = rim;
        if (springOn) {
            step.soften(hertz, dampingRatio, soft);
        }
        tickTotal = 0f;
        tickMotor = 0f;
    }

    /** Updates the effective mass as the axis turns during the tick. */
    void setInverseMass(float inverseMass) {
        invMass = inverseMass;
        mass = inverseMass > 0f ? 1f / inverseMass : 0f;
    }

    /**
     * Scales the stored impulses to the substep and re-applies them.
     *
     * @param step the tick's solver state
     * @param substepScale the ratio of this substep to the one the impulses were accumulated over
     */
    void warmStart(SolverStep step, float substepScale) {
        springImpulse *= substepScale;
        motorImpulse *= substepScale;
        lowerImpulse *= substepScale;
        upperImpulse *= substepScale;
        lockImpulse *= substepScale;
        warm = total();
        tickTotal += warm;
        tickMotor += motorImpulse;
        if (warm != 0f) {
            apply(step, warm);
        }
    }

    private float total() {
        return springImpulse + motorImpulse + lowerImpulse - upperImpulse + lockImpulse;
    }

    /**
     * One pass over the rows, in Box2D's order: spring, motor, limits (or the lock).
     *
     * @param step the tick's solver state
     * @param useBias true for the biased pass
     * @param position the position now (rad or px)
     * @return for the relax pass, the change of the substep's impulse beyond its warm start as a velocity
     */
    float solve(SolverStep step, boolean useBias, float position) {
        if (mass == 0f) {
            return 0f;
        }
        if (locked) {
            lockImpulse += rigidRow(step, useBias, position - lockTarget, lockImpulse, 1f);
        } else {
            if (springOn && hertz > 0f) {
                float impulse = -soft[1] * mass * (velocity(step) + soft[0] * (position - springTarget))
                    - soft[2] * springImpulse;
                springImpulse += impulse;
                push(step, impulse);
            }
            if (motorOn) {
                float limit = maxMotorForce * step.getSubstep();
                float old = motorImpulse;
                float next = old + mass * (motorSpeed - velocity(step));
                motorImpulse = next < -limit ? -limit : (next > limit ? limit : next);
                tickMotor += motorImpulse - old;
                push(step, motorImpulse - old);
            }
            if (limitOn) {
                float old = lowerImpulse;
                lowerImpulse = Math.max(0f, old + rigidRow(step, useBias, position - lower, old, 1f));
                push(step, lowerImpulse - old);
                old = upperImpulse;
                upperImpulse = Math.max(0f, old + rigidRow(step, useBias, upper - position, old, -1f));
                push(step, old - upperImpulse);
            }
        }
        return useBias ? 0f : Math.abs((total() - warm) * invMass) * scale;
    }

    /** Applies an impulse and counts it in the tick. */
    private void push(SolverStep step, float impulse) {
        tickTotal += impulse;
        apply(step, impulse);
    }

    /**
     * The impulse of a row that holds c ≥ 0 (or c = 0 when locked), c growing with sign·position:
     * a gap ahead only slows the approach enough to close it in this substep; an overlap is pushed
     * out with the world's joint softness in the biased pass and not at all in the relax pass.
     */
    private float rigidRow(SolverStep step, boolean useBias, float c, float accumulated, float sign) {
        float bias = 0f;
        float massScale = 1f;
        float impulseScale = 0f;
        if (c > 0f && !locked) {
            bias = c * step.getInverseSubstep();
        } else if (useBias) {
            float max = step.getJointPushMaxVelocity() / scale;
            bias = step.getJointBiasRate() * c;
            bias = bias < -max ? -max : (bias > max ? max : bias);
            massScale = step.getJointMassScale();
            impulseScale = step.getJointImpulseScale();
        }
        float cdot = sign * velocity(step);
        return -massScale * mass * (cdot + bias) - impulseScale * accumulated;
    }

    /**
     * Called once after the substeps.
     *
     * @param timestep the tick's length (s)
     */
    void finish(float timestep) {
        force = tickTotal / timestep;
        motorForce = tickMotor / timestep;
    }
}
