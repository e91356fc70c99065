package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;
import org.emini.shape.Shape;

/**
 * What joints and springs share: two bodies, an anchor on each in the body's own frame (it may lie
 * outside the body), and the anchors' geometry during a tick.
 *
 * <p>Anchor arms are rotated by each body's rotation since the tick began, and the anchors'
 * separation is measured from the bodies' motion since then ({@link SolverStep#getDeltaX(int)} and
 * friends), as the contacts do: the error is exact at every substep, so the joint does not drift.
 *
 * <p>Only this package extends it; an application's own constraints implement
 * {@link Constraint} directly.
 */
public abstract class TwoBodyConstraint implements Constraint {
    final Body bodyA;
    final Body bodyB;
    final float localAX;
    final float localAY;
    final float localBX;
    final float localBY;

    // Fixed over a tick: solver indices, inverse masses, arms and centre offset at the start.
    int ia;
    int ib;
    float mA;
    float iA;
    float mB;
    float iB;
    private float rA0x;
    private float rA0y;
    private float rB0x;
    private float rB0y;
    private float centreX;
    private float centreY;
    /** Turns an angular velocity change into a speed at the bodies' rims (px). */
    float radius;

    // Current arms (world orientation) and anchor separation B − A, set by arms().
    float rAx;
    float rAy;
    float rBx;
    float rBy;
    float sepX;
    float sepY;

    /** The substep the accumulated impulses were computed over. */
    private float impulseSubstep;
    /** What {@link #getForce()} reports. */
    float force;
    private float breakForce = Float.POSITIVE_INFINITY;
    private Object userData;

    TwoBodyConstraint(String where, Body a, Body b, float ax, float ay, float bx, float by) {
        Require.inWorld(where, "body a", a);
        Require.inWorld(where, "body b", b);
        if (a == b) {
            throw new IllegalArgumentException(where + ": the two bodies must differ, both were " + a);
        }
        if (a.getWorld() != b.getWorld()) {
            throw new IllegalArgumentException(where + ": " + a + " and " + b + " are in different worlds");
        }
        bodyA = a;
        bodyB = b;
        localAX = anchor(where, "anchor a x", ax);
        localAY = anchor(where, "anchor a y", ay);
        localBX = anchor(where, "anchor b x", bx);
        localBY = anchor(where, "anchor b y", by);
    }

    /** A local anchor coordinate: finite and within Shape.MAX_EXTENT of its body, where lever arms stay in range. */
    private static float anchor(String where, String what, float value) {
        Check.finite(where, what, value);
        if (Math.abs(value) > Shape.MAX_EXTENT) {
            throw new IllegalArgumentException(where + ": " + what + " is " + value + " px from its body, beyond"
                + " Shape.MAX_EXTENT (" + Shape.MAX_EXTENT + " px)");
        }
        return value;
    }

    /** Reads the bodies' solver state at the start of a tick; false when both bodies are fixed. */
    boolean prepareAnchors(SolverStep step) {
        ia = step.indexOf(bodyA);
        ib = step.indexOf(bodyB);
        mA = step.getInverseMass(ia);
        iA = step.getInverseInertia(ia);
        mB = step.getInverseMass(ib);
        iB = step.getInverseInertia(ib);
        float ca = bodyA.getCos();
        float sa = bodyA.getSin();
        float cb = bodyB.getCos();
        float sb = bodyB.getSin();
        rA0x = ca * localAX - sa * localAY;
        rA0y = sa * localAX + ca * localAY;
        rB0x = cb * localBX - sb * localBY;
        rB0y = sb * localBX + cb * localBY;
        centreX = bodyB.getX() - bodyA.getX();
        centreY = bodyB.getY() - bodyA.getY();
        // The moving bodies' rims: a large static body turns nothing.
        radius = Math.max(ia != 0 ? bodyA.getShape().getBoundingRadius() : 0f,
            ib != 0 ? bodyB.getShape().getBoundingRadius() : 0f);
        return ia != 0 || ib != 0;
    }

    /** Sets the current arms and the anchors' separation from the motion since the tick began. */
    void arms(SolverStep step) {
        float c = step.getDeltaCos(ia);
        float s = step.getDeltaSin(ia);
        rAx = c * rA0x - s * rA0y;
        rAy = s * rA0x + c * rA0y;
        c = step.getDeltaCos(ib);
        s = step.getDeltaSin(ib);
        rBx = c * rB0x - s * rB0y;
        rBy = s * rB0x + c * rB0y;
        sepX = step.getDeltaX(ib) - step.getDeltaX(ia) + centreX + rBx - rAx;
        sepY = step.getDeltaY(ib) - step.getDeltaY(ia) + centreY + rBy - rAy;
    }

    /** x of the relative velocity of the anchors, B's minus A's. */
    float relativeVelocityX(SolverStep step) {
        return step.getVelocityX(ib) - step.getAngularVelocity(ib) * rBy
            - step.getVelocityX(ia) + step.getAngularVelocity(ia) * rAy;
    }

    /** y of the relative velocity of the anchors, B's minus A's. */
    float relativeVelocityY(SolverStep step) {
        return step.getVelocityY(ib) + step.getAngularVelocity(ib) * rBx
            - step.getVelocityY(ia) - step.getAngularVelocity(ia) * rAx;
    }

    /** Applies a linear impulse at the anchors: +p to B, −p to A. */
    void applyLinear(SolverStep step, float px, float py) {
        step.applyImpulse(ia, -px, -py, rAx, rAy);
        step.applyImpulse(ib, px, py, rBx, rBy);
    }

    /**
     * Applies a linear impulse with given angular parts: +p and +lb to B, −p and −la to A (for rows
     * whose lever arms are not the anchors', such as a slide axis fixed in A).
     */
    void applyLever(SolverStep step, float px, float py, float la, float lb) {
        step.applyImpulse(ia, -px, -py, 0f, 0f);
        step.applyAngularImpulse(ia, -la);
        step.applyImpulse(ib, px, py, 0f, 0f);
        step.applyAngularImpulse(ib, lb);
    }

    /** A linear position correction, rate times error, capped at the joint push speed (px/s). */
    static float pushBias(SolverStep step, float rate, float error) {
        float max = step.getJointPushMaxVelocity();
        float bias = rate * error;
        return bias < -max ? -max : (bias > max ? max : bias);
    }

    /** An angular position correction (rad/s), capped so that the bodies' rims move at most the joint push speed. */
    float turnBias(SolverStep step, float rate, float error) {
        float max = radius > 0f ? step.getJointPushMaxVelocity() / radius : Float.POSITIVE_INFINITY;
        float bias = rate * error;
        return bias < -max ? -max : (bias > max ? max : bias);
    }

    /**
     * The factor to scale accumulated impulses by before warm starting: impulses are per substep,
     * and the substep changes with the timestep, the iteration count and dynamic iterations.
     */
    float substepScale(SolverStep step) {
        float h = step.getSubstep();
        float old = impulseSubstep;
        impulseSubstep = h;
        return old == 0f ? 1f : h / old;
    }

    @Override
    public int getBodyCount() {
        return 2;
    }

    @Override
    public Body getBody(int index) {
        if (index != 0 && index != 1) {
            throw new IndexOutOfBoundsException("Constraint.getBody: index " + index + " of 2");
        }
        return index == 0 ? bodyA : bodyB;
    }

    /**
     * The first body.
     *
     * @return body A
     */
    public Body getBodyA() {
        return bodyA;
    }

    /**
     * The second body.
     *
     * @return body B
     */
    public Body getBodyB() {
        return bodyB;
    }

    /**
     * The x of the anchor on body A, in A's own frame.
     *
     * @return x (px)
     */
    public float getLocalAnchorAX() {
        return localAX;
    }

    /**
     * The y of the anchor on body A, in A's own frame.
     *
     * @return y (px)
     */
    public float getLocalAnchorAY() {
        return localAY;
    }

    /**
     * The x of the anchor on body B, in B's own frame.
     *
     * @return x (px)
     */
    public float getLocalAnchorBX() {
        return localBX;
    }

    /**
     * The y of the anchor on body B, in B's own frame.
     *
     * @return y (px)
     */
    public float getLocalAnchorBY() {
        return localBY;
    }

    /**
     * The world x of the anchor on body A, where A is now (the original's {@code getPoint1}).
     *
     * @return x (px)
     */
    public float getAnchorAX() {
        return bodyA.toWorldX(localAX, localAY);
    }

    /**
     * The world y of the anchor on body A, where A is now.
     *
     * @return y (px)
     */
    public float getAnchorAY() {
        return bodyA.toWorldY(localAX, localAY);
    }

    /**
     * The world x of the anchor on body B, where B is now (the original's {@code getPoint2}).
     *
     * @return x (px)
     */
    public float getAnchorBX() {
        return bodyB.toWorldX(localBX, localBY);
    }

    /**
     * The world y of the anchor on body B, where B is now.
     *
     * @return y (px)
     */
    public float getAnchorBY() {
        return bodyB.toWorldY(localBX, localBY);
    }

    /**
     * Stops the two bodies from colliding with each other by putting both on a collision layer
     * (bodies that share a layer do not collide). Joined bodies that also collide fight each other:
     * the manual's advice is to do this for every pin joint whose bodies touch.
     *
     * @param layer the layer, 0 to 31; other bodies on it stop colliding with these two as well
     */
    public void setCollisionLayer(int layer) {
        bodyA.addCollisionLayer(layer);
        bodyB.addCollisionLayer(layer);
    }

    @Override
    public boolean concernsBody(Body body) {
        return body == bodyA || body == bodyB;
    }

    @Override
    public float getForce() {
        return force;
    }

    /**
     * Makes the constraint breakable: once {@link #getForce()} exceeds this after a tick, the
     * world removes it as the tick ends and lists it in the tick's
     * {@link org.emini.dynamics.StepData#getBrokenConstraint(int)}.
     *
     * @param maxForce the force (mass·px/s², as {@link #getForce()} reports it), &ge; 0;
     *     Float.POSITIVE_INFINITY (the default) never breaks
     */
    public void setBreakForce(float maxForce) {
        breakForce = Check.limit(getClass().getSimpleName() + ".setBreakForce", "maxForce", maxForce);
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
     * Attaches an application object to this constraint.
     *
     * @param userData any object, or null
     */
    public void setUserData(Object userData) {
        this.userData = userData;
    }

    /** Gives a copy this constraint's break force and user data (what every kind shares). */
    <T extends TwoBodyConstraint> T copyCommon(T copy) {
        copy.setBreakForce(breakForce);
        copy.setUserData(userData);
        return copy;
    }
}
