package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;

/**
 * Drags a point of a body toward a target in the world, as an editor's mouse or a touch does: a
 * soft spring-damper of given frequency and damping ratio (it behaves the same whatever the
 * body's mass) whose force never exceeds a cap. Box2D's {@code MouseJoint}; in pymunk a PivotJoint
 * to a kinematic body with max_force and error_bias.
 *
 * <p>Far from the target the pull is the cap, so the body accelerates at no more than
 * maxForce/m; the spring never asks for more speed than the cap can stop from (√(2·0.9·a·d) at a
 * distance d, a = maxForce/m), so a capped drag brakes in time and arrives in about the time a
 * body limited to a needs, instead of overshooting and circling; near the target the
 * spring-damper settles the point on it. The body turns freely about the point (damp it with the
 * world's rotational damping if it spins).
 *
 * <p>Example:
 * <pre>{@code
 * MouseJoint drag = new MouseJoint(body, touchX, touchY, 1000f * body.getMass());
 * world.addConstraint(drag);
 * // on every move: drag.setTarget(touchX, touchY); on release: world.removeConstraint(drag);
 * }</pre>
 */
public final class MouseJoint implements Constraint {
    private final Body body;
    private final float localX;
    private final float localY;
    private float targetX;
    private float targetY;
    private float maxForce;
    private float hertz = 5f;
    private float dampingRatio = 0.7f;
    private float breakForce = Float.POSITIVE_INFINITY;

    private final SoftPoint point = new SoftPoint();
    private int index;
    private float im;
    private float ii;
    private float r0x;
    private float r0y;
    private float x0;
    private float y0;
    private float rx;
    private float ry;
    private float impulseSubstep;
    private float force;

    /**
     * Grabs a body at a world point on it (or off it) and pulls that point toward the same point:
     * move the target with {@link #setTarget}.
     *
     * @param body the body, in a world
     * @param x the grabbed point's world x (px), also the first target
     * @param y the grabbed point's world y (px)
     * @param maxForce the largest pull (mass·px/s²), &ge; 0; Float.POSITIVE_INFINITY for no limit
     */
    public MouseJoint(Body body, float x, float y, float maxForce) {
        this.body = Require.inWorld("MouseJoint", "body", body);
        Check.finite("MouseJoint", "x", x);
        Check.finite("MouseJoint", "y", y);
        localX = body.toLocalX(x, y);
        localY = body.toLocalY(x, y);
        targetX = x;
        targetY = y;
        this.maxForce = Check.limit("MouseJoint", "maxForce", maxForce);
    }

    /**
     * Moves the target, waking the body.
     *
     * @param x the target's world x (px)
     * @param y the target's world y (px)
     */
    public void setTarget(float x, float y) {
        targetX = Check.finite("MouseJoint.setTarget", "x", x);
        targetY = Check.finite("MouseJoint.setTarget", "y", y);
        body.wakeUp();
    }

    /**
     * The target's x.
     *
     * @return x (px)
     */
    public float getTargetX() {
        return targetX;
    }

    /**
     * The target's y.
     *
     * @return y (px)
     */
    public float getTargetY() {
        return targetY;
    }

    /**
     * The grabbed point's world x, where the body is now.
     *
     * @return x (px)
     */
    public float getAnchorX() {
        return body.toWorldX(localX, localY);
    }

    /**
     * The grabbed point's world y, where the body is now.
     *
     * @return y (px)
     */
    public float getAnchorY() {
        return body.toWorldY(localX, localY);
    }

    /**
     * The pull's cap.
     *
     * @return the force (mass·px/s²)
     */
    public float getMaxForce() {
        return maxForce;
    }

    /**
     * Sets the pull's cap.
     *
     * @param maxForce the force (mass·px/s²), &ge; 0; Float.POSITIVE_INFINITY for no limit
     */
    public void setMaxForce(float maxForce) {
        this.maxForce = Check.limit("MouseJoint.setMaxForce", "maxForce", maxForce);
    }

    /**
     * Sets the spring-damper (by default 5 Hz, damping ratio 0.7).
     *
     * @param hertz the natural frequency (Hz), &gt; 0
     * @param dampingRatio the damping ratio, &ge; 0 (1 is critical)
     */
    public void setSpring(float hertz, float dampingRatio) {
        this.hertz = Check.positive("MouseJoint.setSpring", "hertz", hertz);
        this.dampingRatio = Check.nonNegative("MouseJoint.setSpring", "dampingRatio", dampingRatio);
    }

    /**
     * The spring-damper's frequency.
     *
     * @return the frequency (Hz)
     */
    public float getSpringHertz() {
        return hertz;
    }

    /**
     * The spring-damper's damping ratio.
     *
     * @return ζ
     */
    public float getSpringDampingRatio() {
        return dampingRatio;
    }

    /**
     * Makes the joint breakable (see {@link Constraint#getBreakForce()}).
     *
     * @param maxForce the force (mass·px/s²), &ge; 0; Float.POSITIVE_INFINITY (the default) never breaks
     */
    public void setBreakForce(float maxForce) {
        breakForce = Check.limit("MouseJoint.setBreakForce", "maxForce", maxForce);
    }

    @Override
    public float getBreakForce() {
        return breakForce;
    }

    /**
     * The body it drags.
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
    public Body getBody(int i) {
        if (i != 0) {
            throw new IndexOutOfBoundsException("Constraint.getBody: index " + i + " of 1");
        }
        return body;
    }

    @Override
    public boolean concernsBody(Body b) {
        return b == body;
    }

    @Override
    public void prepare(SolverStep step) {
        index = step.indexOf(body);
        im = step.getInverseMass(index);
        ii = step.getInverseInertia(index);
        float c = body.getCos();
        float s = body.getSin();
        r0x = c * localX - s * localY;
        r0y = s * localX + c * localY;
        x0 = body.getX();
        y0 = body.getY();
        step.soften(hertz, dampingRatio, point.soft);
        point.beginTick();
    }

    @Override
    public void warmStart(SolverStep step) {
        if (index == 0) {
            return;
        }
        float h = step.getSubstep();
        point.warmStart(impulseSubstep == 0f ? 1f : h / impulseSubstep);
        impulseSubstep = h;
        arm(step);
        step.applyImpulse(index, point.impulseX(), point.impulseY(), rx, ry);
    }

    private void arm(SolverStep step) {
        float c = step.getDeltaCos(index);
        float s = step.getDeltaSin(index);
        rx = c * r0x - s * r0y;
        ry = s * r0x + c * r0y;
    }

    @Override
    public float solve(SolverStep step, boolean useBias) {
        if (index == 0) {
            return 0f;
        }
        arm(step);
        float w = step.getAngularVelocity(index);
        float cx = step.getVelocityX(index) - w * ry;
        float cy = step.getVelocityY(index) + w * rx;
        float ex = x0 + step.getDeltaX(index) + rx - targetX;
        float ey = y0 + step.getDeltaY(index) + ry - targetY;
        point.solve(cx, cy, ex, ey, im + ii * ry * ry, -ii * rx * ry, im + ii * rx * rx, maxForce * step.getSubstep(),
            maxForce * im);
        step.applyImpulse(index, point.dx, point.dy, rx, ry);
        return useBias ? 0f : point.change();
    }

    @Override
    public void finish(SolverStep step) {
        force = point.force(step.getTimestep());
    }

    /**
     * The pull in the last tick, averaged over it.
     *
     * @return the force's magnitude (mass·px/s²)
     */
    @Override
    public float getForce() {
        return force;
    }

    @Override
    public String toString() {
        return "MouseJoint(" + body + ", target (" + targetX + ", " + targetY + "))";
    }
}
