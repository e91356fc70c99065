package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.CopyMapping;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * A motor: drives one body's velocity towards a target with a limited force, as the original
 * engine's motors do. If the force does not suffice (against gravity, friction or a load), the
 * target is not reached.
 *
 * <p>A <em>rotational</em> motor drives the angular velocity. A <em>linear</em> motor drives the
 * velocity along the target's direction to the target's speed and leaves the perpendicular motion
 * free, so an axis whose target is 0 is not constrained (a target of (0, 0) does nothing). In
 * <em>orthogonal</em> mode a linear motor drives the whole velocity vector to the target instead,
 * braking the perpendicular motion. In <em>relative</em> mode the linear target is given in the
 * body's own frame and turns with the body. The force is limited per axis (of the world, or of the
 * body in relative mode), as in the original.
 *
 * <p>The limit applies per substep: the impulse accumulated over a substep h is clamped to
 * maxForce·h, so the motor never exerts more than maxForce on average. A motor acts through the
 * body's own mass: on a static body it does nothing.
 *
 * <p>An application may extend it, as the manual's game does with its sprite control: a subclass
 * may override {@link #prepare(SolverStep)} (the original's {@code precalculate}), which runs once
 * per tick before the solve, to change the target or give the body an impulse or velocity that acts
 * in that tick, and must call {@code super.prepare(step)}. The solve itself ({@code warmStart},
 * {@code solve}, {@code finish}) is final. A subclass that is copied with its world overrides
 * {@link #copy(CopyMapping)}, which otherwise makes a plain {@code Motor}.
 *
 * <pre>{@code
 * class SpriteControl extends Motor {
 *     float jump;                                   // set by the input, px/s upwards
 *     SpriteControl(Body sprite) {
 *         super(sprite, 0f, 0f, 1000f);             // linear, x driven by setTargetVelocity(v, 0)
 *     }
 *     public void prepare(SolverStep step) {
 *         if (jump != 0f) {
 *             getBody().applyAcceleration(0f, -jump, 1f);   // the velocity changes in this tick
 *             jump = 0f;
 *         }
 *         super.prepare(step);
 *     }
 * }
 * }</pre>
 */
public class Motor implements Constraint {
    private final Body body;
    private boolean rotational;
    private boolean relative;
    private boolean orthogonal;
    private float targetX;
    private float targetY;
    private float targetAngular;
    private float maxForce;
    // The linear target as a unit direction and a speed, for the non-orthogonal mode.
    private float dirX;
    private float dirY;
    private float speed;

    private int index;
    private float mass;
    private float inertia;
    private float radius;
    private float impulseSubstep;
    // Impulses of the current substep in the motor's frame: x, y (or along the direction in x).
    private float accX;
    private float accY;
    private float accAngular;
    // The impulses this substep warm-started with: the relax pass reports the change from them.
    private float warmX;
    private float warmY;
    private float warmAngular;
    // All impulses applied in the tick, in world axes.
    private float tickX;
    private float tickY;
    private float tickAngular;
    private float force;
    private float breakForce = Float.POSITIVE_INFINITY;
    private Object userData;
    // The motor's frame in the current solve (the body's rotation in relative mode).
    private float frameC = 1f;
    private float frameS;

    /**
     * Creates a rotational motor.
     *
     * @param body the body, in a world
     * @param targetAngularVelocity the target ω (rad/s); positive grows the angle
     * @param maxTorque the largest torque (mass·px²/s²), &ge; 0; Float.POSITIVE_INFINITY for no limit
     */
    public Motor(Body body, float targetAngularVelocity, float maxTorque) {
        this.body = Require.inWorld("Motor", "body", body);
        setTargetAngularVelocity(targetAngularVelocity);
        setMaxForce(maxTorque);
    }

    /**
     * Creates a linear motor.
     *
     * @param body the body, in a world
     * @param targetVelocityX the target x velocity (px/s); 0 leaves x free unless orthogonal
     * @param targetVelocityY the target y velocity (px/s); 0 leaves y free unless orthogonal
     * @param maxForce the largest force per axis (mass·px/s²), &ge; 0; Float.POSITIVE_INFINITY for
     *     no limit
     */
    public Motor(Body body, float targetVelocityX, float targetVelocityY, float maxForce) {
        this.body = Require.inWorld("Motor", "body", body);
        setTargetVelocity(targetVelocityX, targetVelocityY);
        setMaxForce(maxForce);
    }

    /**
     * The body the motor drives.
     *
     * @return the body
     */
    public Body getBody() {
        return body;
    }

    @Override
    public int getBodyCount() {
        return 1;
    }

    @Override
    public Body getBody(int index) {
        if (index != 0) {
            throw new IndexOutOfBoundsException("Constraint.getBody: index " + index + " of 1");
        }
        return body;
    }

    /**
     * Whether the motor drives the angular velocity.
     *
     * @return true for a rotational motor, false for a linear one
     */
    public boolean isRotational() {
        return rotational;
    }

    /**
     * Makes the motor linear with a target velocity.
     *
     * @param vx the target x velocity (px/s)
     * @param vy the target y velocity (px/s)
     */
    public void setTargetVelocity(float vx, float vy) {
        targetX = Check.finite("Motor.setTargetVelocity", "vx", vx);
        targetY = Check.finite("Motor.setTargetVelocity", "vy", vy);
        speed = EMath.sqrt(vx * vx + vy * vy);
        dirX = speed > 0f ? vx / speed : 0f;
        dirY = speed > 0f ? vy / speed : 0f;
        if (rotational) {
            rotational = false;
            clearImpulses();
        }
    }

    /**
     * Makes the motor rotational with a target angular velocity.
     *
     * @param omega the target ω (rad/s)
     */
    public void setTargetAngularVelocity(float omega) {
        targetAngular = Check.finite("Motor.setTargetAngularVelocity", "omega", omega);
        if (!rotational) {
            rotational = true;
            clearImpulses();
        }
    }

    /**
     * The linear target's x.
     *
     * @return vx (px/s)
     */
    public float getTargetVelocityX() {
        return targetX;
    }

    /**
     * The linear target's y.
     *
     * @return vy (px/s)
     */
    public float getTargetVelocityY() {
        return targetY;
    }

    /**
     * The rotational target.
     *
     * @return ω (rad/s)
     */
    public float getTargetAngularVelocity() {
        return targetAngular;
    }

    /**
     * The force (linear) or torque (rotational) limit.
     *
     * @return the limit
     */
    public float getMaxForce() {
        return maxForce;
    }

    /**
     * Sets the force limit: per axis for a linear motor, a torque for a rotational one.
     *
     * @param maxForce the limit, &ge; 0; Float.POSITIVE_INFINITY for no limit
     */
    public void setMaxForce(float maxForce) {
        this.maxForce = Check.limit("Motor.setMaxForce", "maxForce", maxForce);
    }

    /**
     * Whether a linear target is in the body's frame.
     *
     * @return true in relative mode
     */
    public boolean isRelative() {
        return relative;
    }

    /**
     * Gives a linear target in the body's own frame (it turns with the body), or in the world's.
     *
     * @param relative true for the body's frame
     */
    public void setRelative(boolean relative) {
        if (this.relative != relative) {
            this.relative = relative;
            clearImpulses();
        }
    }

    /**
     * Whether a linear motor drives the whole velocity, braking perpendicular motion.
     *
     * @return true in orthogonal mode
     */
    public boolean isOrthogonal() {
        return orthogonal;
    }

    /**
     * Drives the whole velocity vector to the target (true), or only the velocity along the target
     * direction (false, the default).
     *
     * @param orthogonal true to brake perpendicular motion too
     */
    public void setOrthogonal(boolean orthogonal) {
        if (this.orthogonal != orthogonal) {
            this.orthogonal = orthogonal;
            clearImpulses();
        }
    }

    private void clearImpulses() {
        accX = 0f;
        accY = 0f;
        accAngular = 0f;
    }

    @Override
    public final boolean concernsBody(Body b) {
        return b == body;
    }

    @Override
    public void prepare(SolverStep step) {
        index = step.indexOf(body);
        float im = step.getInverseMass(index);
        float ii = step.getInverseInertia(index);
        mass = im > 0f ? 1f / im : 0f;
        inertia = ii > 0f ? 1f / ii : 0f;
        radius = body.getShape().getBoundingRadius();
        tickX = 0f;
        tickY = 0f;
        tickAngular = 0f;
    }

    @Override
    public final void warmStart(SolverStep step) {
        if (index == 0) {
            return;
        }
        float h = step.getSubstep();
        if (impulseSubstep != 0f && impulseSubstep != h) {
            float scale = h / impulseSubstep;
            accX *= scale;
            accY *= scale;
            accAngular *= scale;
        }
        impulseSubstep = h;
        warmX = accX;
        warmY = accY;
        warmAngular = accAngular;
        // Count every impulse applied in the tick: substeps after convergence only warm start.
        if (rotational) {
            step.applyAngularImpulse(index, accAngular);
            tickAngular += accAngular;
        } else {
            frame(step);
            applyLocal(step, impulseX(), impulseY());
        }
    }

    @Override
    public final float solve(SolverStep step, boolean useBias) {
        if (index == 0) {
            return 0f;
        }
        float limit = maxForce * step.getSubstep();
        float change;
        if (rotational) {
            if (inertia == 0f) {
                return 0f;
            }
            float old = accAngular;
            accAngular = clamp(old - inertia * (step.getAngularVelocity(index) - targetAngular), limit);
            float d = accAngular - old;
            step.applyAngularImpulse(index, d);
            tickAngular += d;
            change = useBias ? 0f : Math.abs((accAngular - warmAngular) / inertia) * radius;
        } else {
            if (mass == 0f || (speed == 0f && !orthogonal)) {
                return 0f;
            }
            frame(step);
            float vx = step.getVelocityX(index);
            float vy = step.getVelocityY(index);
            // The velocity in the motor's frame.
            float lx = frameC * vx + frameS * vy;
            float ly = -frameS * vx + frameC * vy;
            float dx;
            float dy;
            if (orthogonal) {
                float oldX = accX;
                float oldY = accY;
                accX = clamp(oldX - mass * (lx - targetX), limit);
                accY = clamp(oldY - mass * (ly - targetY), limit);
                dx = accX - oldX;
                dy = accY - oldY;
            } else {
                // One constraint along the direction; its impulse's components stay within the limit.
                float old = accX;
                accX = clamp(old - mass * (lx * dirX + ly * dirY - speed), limit / Math.max(Math.abs(dirX), Math.abs(dirY)));
                float d = accX - old;
                dx = d * dirX;
                dy = d * dirY;
            }
            applyLocal(step, dx, dy);
            change = useBias ? 0f : Math.max(Math.abs(accX - warmX), Math.abs(accY - warmY)) / mass;
        }
        return change;
    }

    /** x of the substep's linear impulse in the motor's frame (accX is along the direction unless orthogonal). */
    private float impulseX() {
        return orthogonal ? accX : accX * dirX;
    }

    /** y of the substep's linear impulse in the motor's frame. */
    private float impulseY() {
        return orthogonal ? accY : accX * dirY;
    }

    /** The motor's frame now: the body's current rotation in relative mode, else the world's. */
    private void frame(SolverStep step) {
        if (!relative) {
            frameC = 1f;
            frameS = 0f;
            return;
        }
        float c = body.getCos();
        float s = body.getSin();
        float dc = step.getDeltaCos(index);
        float ds = step.getDeltaSin(index);
        frameC = c * dc - s * ds;
        frameS = s * dc + c * ds;
    }

    /** Applies an impulse given in the motor's frame, and counts it in world axes. */
    private void applyLocal(SolverStep step, float jx, float jy) {
        float wx = frameC * jx - frameS * jy;
        float wy = frameS * jx + frameC * jy;
        step.applyImpulse(index, wx, wy, 0f, 0f);
        tickX += wx;
        tickY += wy;
    }

    private static float clamp(float value, float limit) {
        return value < -limit ? -limit : (value > limit ? limit : value);
    }

    @Override
    public final void finish(SolverStep step) {
        float inv = 1f / step.getTimestep();
        force = rotational ? Math.abs(tickAngular) * inv : EMath.length(tickX, tickY) * inv;
    }

    /**
     * The force (linear) or torque (rotational) the motor exerted in the last tick, averaged over
     * it.
     *
     * @return the magnitude (mass·px/s², or mass·px²/s² for a rotational motor)
     */
    @Override
    public final float getForce() {
        return force;
    }

    /**
     * Makes the motor breakable: once {@link #getForce()} exceeds this after a tick, the world
     * removes it as the tick ends and lists it in the tick's
     * {@link org.emini.dynamics.StepData#getBrokenConstraint(int)}.
     *
     * @param maxForce the force (or torque, for a rotational motor), &ge; 0; Float.POSITIVE_INFINITY
     *     (the default) never breaks
     */
    public void setBreakForce(float maxForce) {
        breakForce = Check.limit("Motor.setBreakForce", "maxForce", maxForce);
    }

    @Override
    public float getBreakForce() {
        return breakForce;
    }

    @Override
    public Object getUserData() {
        return userData;
    }

    /**
     * Attaches an application object to this motor.
     *
     * @param userData any object, or null
     */
    public void setUserData(Object userData) {
        this.userData = userData;
    }

    @Override
    public Motor copy(CopyMapping mapping) {
        Motor copy = rotational ? new Motor(mapping.body(body), targetAngular, maxForce)
            : new Motor(mapping.body(body), targetX, targetY, maxForce);
        copy.relative = relative;
        copy.orthogonal = orthogonal;
        copy.breakForce = breakForce;
        copy.userData = userData;
        return copy;
    }

    @Override
    public String toString() {
        return "Motor(" + body + (rotational ? ", ω " + targetAngular : ", v (" + targetX + ", " + targetY + ")") + ")";
    }
}
