package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;

/**
 * Drives body B's position and angle relative to body A toward a target offset, with a capped
 * force and torque: a top-down character pushed around by its controller, a moving platform
 * following a path relative to the ground. Box2D's {@code MotorJoint}.
 *
 * <p>The target is B's centre at a linear offset in A's frame (it turns with A) and B's angle at
 * an angular offset from A's. Each is pulled by a soft spring-damper (by default 5 Hz, critically
 * damped: it behaves the same whatever the masses), whose force and torque are capped; with the
 * caps large, B reaches the target in about a period of the spring. With the caps small, the pull
 * speed is kept to what the cap can stop from (as {@link MouseJoint}'s), so B brakes in time.
 *
 * <p>Example, a platform that moves to 200 px right of its start over the static ground:
 * <pre>{@code
 * MotorJoint mover = new MotorJoint(ground, platform, 5000f, 1e6f);
 * mover.setLinearOffset(mover.getLinearOffsetX() + 200f, mover.getLinearOffsetY());
 * world.addConstraint(mover);
 * }</pre>
 */
public final class MotorJoint extends TwoBodyConstraint {
    private final SoftPoint point = new SoftPoint();
    private final float[] angularSoft = new float[3];
    private float offsetX;
    private float offsetY;
    private float angularOffset;
    private float maxForce;
    private float maxTorque;
    private float hertz = 5f;
    private float dampingRatio = 1f;

    private boolean active;
    // The offset in world axes at the tick's start, and now (it turns with A).
    private float o0x;
    private float o0y;
    private float ox;
    private float oy;
    private float angularImpulse;
    private float warmAngular;
    private float tickAngular;
    private float torque;

    /**
     * Creates a motor joint whose target is where B is now relative to A.
     *
     * @param a the reference body
     * @param b the driven body
     * @param maxForce the largest force (mass·px/s²), &ge; 0; Float.POSITIVE_INFINITY for no limit
     * @param maxTorque the largest torque (mass·px²/s²), &ge; 0; Float.POSITIVE_INFINITY for no limit
     */
    public MotorJoint(Body a, Body b, float maxForce, float maxTorque) {
        super("MotorJoint", a, b, 0f, 0f, 0f, 0f);
        this.maxForce = Check.limit("MotorJoint", "maxForce", maxForce);
        this.maxTorque = Check.limit("MotorJoint", "maxTorque", maxTorque);
        offsetX = a.toLocalX(b.getX(), b.getY());
        offsetY = a.toLocalY(b.getX(), b.getY());
        angularOffset = b.getAngle() - a.getAngle();
    }

    /**
     * Sets where B's centre should be, in A's frame.
     *
     * @param x the offset's x in A's frame (px)
     * @param y the offset's y in A's frame (px)
     */
    public void setLinearOffset(float x, float y) {
        offsetX = Check.finite("MotorJoint.setLinearOffset", "x", x);
        offsetY = Check.finite("MotorJoint.setLinearOffset", "y", y);
        wake();
    }

    /**
     * The target's x in A's frame.
     *
     * @return x (px)
     */
    public float getLinearOffsetX() {
        return offsetX;
    }

    /**
     * The target's y in A's frame.
     *
     * @return y (px)
     */
    public float getLinearOffsetY() {
        return offsetY;
    }

    /**
     * Sets B's target angle relative to A's.
     *
     * @param angle B's angle minus A's (rad)
     */
    public void setAngularOffset(float angle) {
        angularOffset = Check.finite("MotorJoint.setAngularOffset", "angle", angle);
        wake();
    }

    /**
     * B's target angle relative to A's.
     *
     * @return the angle (rad)
     */
    public float getAngularOffset() {
        return angularOffset;
    }

    /**
     * Sets the force cap.
     *
     * @param maxForce the force (mass·px/s²), &ge; 0; Float.POSITIVE_INFINITY for no limit
     */
    public void setMaxForce(float maxForce) {
        this.maxForce = Check.limit("MotorJoint.setMaxForce", "maxForce", maxForce);
    }

    /**
     * The force cap.
     *
     * @return the force (mass·px/s²)
     */
    public float getMaxForce() {
        return maxForce;
    }

    /**
     * Sets the torque cap.
     *
     * @param maxTorque the torque (mass·px²/s²), &ge; 0; Float.POSITIVE_INFINITY for no limit
     */
    public void setMaxTorque(float maxTorque) {
        this.maxTorque = Check.limit("MotorJoint.setMaxTorque", "maxTorque", maxTorque);
    }

    /**
     * The torque cap.
     *
     * @return the torque (mass·px²/s²)
     */
    public float getMaxTorque() {
        return maxTorque;
    }

    /**
     * Sets the spring-damper that pulls B toward the target (by default 5 Hz, damping ratio 1).
     *
     * @param hertz the natural frequency (Hz), &gt; 0
     * @param dampingRatio the damping ratio, &ge; 0 (1 is critical)
     */
    public void setSpring(float hertz, float dampingRatio) {
        this.hertz = Check.positive("MotorJoint.setSpring", "hertz", hertz);
        this.dampingRatio = Check.nonNegative("MotorJoint.setSpring", "dampingRatio", dampingRatio);
    }

    /**
     * The torque on B in the last tick, averaged over it.
     *
     * @return the magnitude (mass·px²/s²)
     */
    public float getTorque() {
        return torque;
    }

    private void wake() {
        bodyA.wakeUp();
        bodyB.wakeUp();
    }

    @Override
    public void prepare(SolverStep step) {
        active = prepareAnchors(step);
        float c = bodyA.getCos();
        float s = bodyA.getSin();
        o0x = c * offsetX - s * offsetY;
        o0y = s * offsetX + c * offsetY;
        step.soften(hertz, dampingRatio, point.soft);
        step.soften(hertz, dampingRatio, angularSoft);
        point.beginTick();
        tickAngular = 0f;
    }

    /** The offset as A has turned since the tick began. */
    private void offsetNow(SolverStep step) {
        float c = step.getDeltaCos(ia);
        float s = step.getDeltaSin(ia);
        ox = c * o0x - s * o0y;
        oy = s * o0x + c * o0y;
    }

    @Override
    public void warmStart(SolverStep step) {
        if (!active) {
            return;
        }
        float scale = substepScale(step);
        angularImpulse *= scale;
        warmAngular = angularImpulse;
        tickAngular += angularImpulse;
        step.applyAngularImpulse(ia, -angularImpulse);
        step.applyAngularImpulse(ib, angularImpulse);
        point.warmStart(scale);
        offsetNow(step);
        applyPoint(step, point.impulseX(), point.impulseY());
    }

    /** +p on B's centre, −p on A at the offset point (the target turns with A). */
    private void applyPoint(SolverStep step, float px, float py) {
        step.applyImpulse(ia, -px, -py, ox, oy);
        step.applyImpulse(ib, px, py, 0f, 0f);
    }

    @Override
    public float solve(SolverStep step, boolean useBias) {
        if (!active) {
            return 0f;
        }
        float change = 0f;
        float k = iA + iB;
        if (k > 0f) {
            float error = step.getAngle(bodyB) - step.getAngle(bodyA) - angularOffset;
            float cdot = step.getAngularVelocity(ib) - step.getAngularVelocity(ia);
            float cap = maxTorque * step.getSubstep();
            float old = angularImpulse;
            float pull = angularSoft[0] * error;
            float max = SoftPoint.brakingSpeed(maxTorque * k, Math.abs(error));
            pull = pull < -max ? -max : (pull > max ? max : pull);
            float next = old - angularSoft[1] * (cdot + pull) / k - angularSoft[2] * old;
            angularImpulse = next < -cap ? -cap : (next > cap ? cap : next);
            float d = angularImpulse - old;
            tickAngular += d;
            step.applyAngularImpulse(ia, -d);
            step.applyAngularImpulse(ib, d);
            change = Math.abs((angularImpulse - warmAngular) * k) * radius;
        }
        arms(step);
        offsetNow(step);
        float wA = step.getAngularVelocity(ia);
        float cx = step.getVelocityX(ib) - step.getVelocityX(ia) + wA * oy;
        float cy = step.getVelocityY(ib) - step.getVelocityY(ia) - wA * ox;
        float m = mA + mB;
        point.solve(cx, cy, sepX - ox, sepY - oy, m + iA * oy * oy, -iA * ox * oy, m + iA * ox * ox,
            maxForce * step.getSubstep(), maxForce * m);
        applyPoint(step, point.dx, point.dy);
        return useBias ? 0f : Math.max(change, point.change());
    }

    @Override
    public void finish(SolverStep step) {
        float dt = step.getTimestep();
        force = point.force(dt);
        torque = Math.abs(tickAngular) / dt;
    }

    @Override
    public String toString() {
        return "MotorJoint(" + bodyA + ", " + bodyB + ")";
    }
}
