package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.CopyMapping;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * A pin joint: an anchor on each body held at the same point. A loose joint lets the bodies turn
 * freely about it; a fixed joint also locks their relative angle at the angle they have when the
 * joint is created, so the two act as one rigid body (the manual's way to build concave bodies).
 * Either body may be static, and anchors may lie outside the bodies.
 *
 * <p>Solved as Box2D v3 solves its revolute and weld joints: the point constraint as one 2×2 block,
 * the angle (fixed joints) as a scalar before it; the biased pass corrects the position error with
 * the world's joint softness, the relax pass is rigid. Joints that cannot all be satisfied (two pins
 * on one body too far apart) settle into a compromise: the stress they hold turns with the bodies
 * when it is large enough to make their turning unstable. Bodies joined by a pin usually should not
 * collide with each other: see {@link #setCollisionLayer(int)}.
 */
public final class Joint extends TwoBodyConstraint {
    /**
     * The largest geometric gain h·|r·λ|/I per substep a joint's stored impulse keeps unturned
     * (see {@link #turnImpulse}). The explicit limit is 4, but several joints may act on one body
     * and the solve couples them: of 300 random fights of 2 to 4 joints on one body, 11 keep
     * moving with 0.5, 14 with 1, 25 with 2 (44 unturned).
     */
    static final float MAX_TURN_GAIN = 0.5f;

    private final boolean fixed;
    // Relative rotation of B with respect to A when the joint was made (fixed joints hold it).
    private final float referenceCos;
    private final float referenceSin;
    private final float referenceAngle;

    private boolean active;
    // A fixed joint's stiffness, when set (null: rigid, the manual's joint).
    private WeldSoftness softness;
    private float axialMass;
    // Angle error at the start of the tick, as a rotation (exact for any turn of the bodies).
    private float errorCos;
    private float errorSin;
    // Impulses of the current substep, and all impulses applied in the tick.
    private float accX;
    private float accY;
    private float accAngle;
    // The impulses this substep warm-started with: the relax pass reports the change from them.
    private float warmX;
    private float warmY;
    private float warmAngle;
    // The last linearBias result.
    private float biasX;
    private float biasY;
    private float tickX;
    private float tickY;
    private float tickAngle;
    private float torque;
    // The bodies' rotations since the tick began (SolverStep's delta) when the impulse was last
    // applied: the stored linear impulse turns with the bodies from there (see turnImpulse).
    private float appliedCosA = 1f;
    private float appliedSinA;
    private float appliedCosB = 1f;
    private float appliedSinB;

    /**
     * Creates a joint between two bodies that are in the same world.
     *
     * @param a the first body
     * @param b the second body
     * @param ax x of the pivot in a's own frame (px)
     * @param ay y of the pivot in a's own frame (px)
     * @param bx x of the pivot in b's own frame (px)
     * @param by y of the pivot in b's own frame (px)
     * @param fixed true to lock the bodies' relative angle as it is now
     */
    public Joint(Body a, Body b, float ax, float ay, float bx, float by, boolean fixed) {
        super("Joint", a, b, ax, ay, bx, by);
        this.fixed = fixed;
        float ca = a.getCos();
        float sa = a.getSin();
        float cb = b.getCos();
        float sb = b.getSin();
        referenceCos = ca * cb + sa * sb;
        referenceSin = ca * sb - sa * cb;
        referenceAngle = b.getAngle() - a.getAngle();
    }

    /** A copy on other bodies: the same anchors, and the same locked angle whatever the bodies' now. */
    private Joint(Joint j, Body a, Body b) {
        super("Joint.copy", a, b, j.localAX, j.localAY, j.localBX, j.localBY);
        fixed = j.fixed;
        referenceCos = j.referenceCos;
        referenceSin = j.referenceSin;
        referenceAngle = j.referenceAngle;
        if (j.softness != null) {
            setStiffness(j.getLinearHertz(), j.getAngularHertz(), j.getDampingRatio());
        }
    }

    /**
     * {@inheritDoc} A fixed joint's copy locks the same relative angle as this one.
     */
    @Override
    public Joint copy(CopyMapping mapping) {
        return copyCommon(new Joint(this, mapping.body(bodyA), mapping.body(bodyB)));
    }

    /**
     * Creates a joint whose pivot is a world point, where both bodies are now.
     *
     * @param a the first body
     * @param b the second body
     * @param x the pivot's world x (px)
     * @param y the pivot's world y (px)
     * @param fixed true to lock the bodies' relative angle as it is now
     * @return the joint (not yet added to the world)
     */
    public static Joint atWorldPoint(Body a, Body b, float x, float y, boolean fixed) {
        Check.finite("Joint.atWorldPoint", "x", x);
        Check.finite("Joint.atWorldPoint", "y", y);
        Require.inWorld("Joint.atWorldPoint", "body a", a);
        Require.inWorld("Joint.atWorldPoint", "body b", b);
        return new Joint(a, b, a.toLocalX(x, y), a.toLocalY(x, y), b.toLocalX(x, y), b.toLocalY(x, y), fixed);
    }

    /**
     * Whether the joint locks the relative angle.
     *
     * @return true for a fixed joint
     */
    public boolean isFixed() {
        return fixed;
    }

    /**
     * The relative angle (B's angle minus A's) a fixed joint holds: the one at creation.
     *
     * @return the angle (rad)
     */
    public float getReferenceAngle() {
        return referenceAngle;
    }

    /**
     * The magnitude of the torque a fixed joint exerted to hold the angle in the last tick.
     *
     * @return the torque (mass·px²/s²); 0 for loose joints
     */
    public float getTorque() {
        return torque;
    }

    /**
     * Makes a fixed joint soft: its point and its angle become spring-dampers of the given
     * frequencies (a weld that bends and sways, as Box2D's weld joint with hertz set), stable at any
     * frequency. A frequency of 0 keeps that part rigid; both 0 is the manual's rigid joint, solved
     * exactly as before.
     *
     * @param linearHertz the point's natural frequency (Hz), &ge; 0
     * @param angularHertz the angle's natural frequency (Hz), &ge; 0
     * @param dampingRatio the damping ratio of both, &ge; 0 (1 is critical)
     * @throws IllegalStateException for a loose joint (it has no angle to stiffen; use a
     *     {@link RevoluteJoint} with a spring)
     */
    public void setStiffness(float linearHertz, float angularHertz, float dampingRatio) {
        String where = "Joint.setStiffness";
        Check.nonNegative(where, "linearHertz", linearHertz);
        Check.nonNegative(where, "angularHertz", angularHertz);
        Check.nonNegative(where, "dampingRatio", dampingRatio);
        if (!fixed) {
            throw new IllegalStateException(where + ": " + this + " is loose; only a fixed joint has a stiffness"
                + " (a RevoluteJoint has a rotational spring)");
        }
        if (linearHertz == 0f && angularHertz == 0f) {
            softness = null;
            return;
        }
        if (softness == null) {
            softness = new WeldSoftness();
        }
        softness.linearHertz = linearHertz;
        softness.angularHertz = angularHertz;
        softness.dampingRatio = dampingRatio;
    }

    /**
     * The point's stiffness set with {@link #setStiffness}.
     *
     * @return the frequency (Hz), 0 when rigid
     */
    public float getLinearHertz() {
        return softness == null ? 0f : softness.linearHertz;
    }

    /**
     * The angle's stiffness set with {@link #setStiffness}.
     *
     * @return the frequency (Hz), 0 when rigid
     */
    public float getAngularHertz() {
        return softness == null ? 0f : softness.angularHertz;
    }

    /**
     * The damping ratio set with {@link #setStiffness}.
     *
     * @return ζ, 0 when rigid
     */
    public float getDampingRatio() {
        return softness == null ? 0f : softness.dampingRatio;
    }

    @Override
    public void prepare(SolverStep step) {
        if (softness != null) {
            step.soften(softness.linearHertz, softness.dampingRatio, softness.linear);
            step.soften(softness.angularHertz, softness.dampingRatio, softness.angular);
        }
        active = prepareAnchors(step);
        float k = iA + iB;
        axialMass = fixed && k > 0f ? 1f / k : 0f;
        if (axialMass != 0f) {
            // Angle error now: (B's angle − A's angle) − reference, composed as rotations.
            float ca = bodyA.getCos();
            float sa = bodyA.getSin();
            float cb = bodyB.getCos();
            float sb = bodyB.getSin();
            float c = ca * cb + sa * sb;
            float s = ca * sb - sa * cb;
            errorCos = c * referenceCos + s * referenceSin;
            errorSin = s * referenceCos - c * referenceSin;
        }
        tickX = 0f;
        tickY = 0f;
        tickAngle = 0f;
        appliedCosA = 1f;
        appliedSinA = 0f;
        appliedCosB = 1f;
        appliedSinB = 0f;
    }

    @Override
    public void warmStart(SolverStep step) {
        if (!active) {
            return;
        }
        float scale = substepScale(step);
        accX *= scale;
        accY *= scale;
        accAngle *= scale;
        turnImpulse(step);
        warmX = accX;
        warmY = accY;
        warmAngle = accAngle;
        arms(step);
        applyLinear(step, accX, accY);
        step.applyAngularImpulse(ia, -accAngle);
        step.applyAngularImpulse(ib, accAngle);
        // Count every impulse applied in the tick: substeps after convergence only warm start.
        tickX += accX;
        tickY += accY;
        tickAngle += accAngle;
    }

    @Override
    public float solve(SolverStep step, boolean useBias) {
        if (!active) {
            return 0f;
        }
        float change = 0f;
        float biasRate = useBias ? step.getJointBiasRate() : 0f;
        float massScale = useBias ? step.getJointMassScale() : 1f;
        float impulseScale = useBias ? step.getJointImpulseScale() : 0f;
        if (axialMass != 0f && softness == null) {
            arms(step);
            float weld = solveWeld(step, useBias, biasRate, massScale, impulseScale);
            if (weld >= 0f) {
                return weld;
            }
        }
        if (axialMass != 0f) {
            float bias = 0f;
            float rowMass = massScale;
            float rowImpulse = impulseScale;
            if (softness != null && softness.angularHertz > 0f) {
                // A soft weld's angle is a spring: it acts in both passes, unclamped.
                bias = softness.angular[0] * angleError(step);
                rowMass = softness.angular[1];
                rowImpulse = softness.angular[2];
            } else if (useBias) {
                bias = angularBias(step, biasRate);
            }
            float cdot = step.getAngularVelocity(ib) - step.getAngularVelocity(ia);
            float impulse = -axialMass * rowMass * (cdot + bias) - rowImpulse * accAngle;
            accAngle += impulse;
            tickAngle += impulse;
            step.applyAngularImpulse(ia, -impulse);
            step.applyAngularImpulse(ib, impulse);
            change = useBias ? 0f : Math.abs((accAngle - warmAngle) / axialMass) * radius;
        }

        arms(step);
        float cx = relativeVelocityX(step);
        float cy = relativeVelocityY(step);
        if (softness != null && softness.linearHertz > 0f) {
            // A soft weld's point is a spring: it acts in both passes, unclamped.
            cx += softness.linear[0] * sepX;
            cy += softness.linear[0] * sepY;
            massScale = softness.linear[1];
            impulseScale = softness.linear[2];
        } else if (useBias) {
            linearBias(step, biasRate);
            cx += biasX;
            cy += biasY;
        }
        // K = J M⁻¹ Jᵀ for the point constraint.
        float m = mA + mB;
        float k11 = m + iA * rAy * rAy + iB * rBy * rBy;
        float k12 = -iA * rAy * rAx - iB * rBy * rBx;
        float k22 = m + iA * rAx * rAx + iB * rBx * rBx;
        float det = k11 * k22 - k12 * k12;
        if (det > 0f) {
            float inv = 1f / det;
            float px = -massScale * inv * (k22 * cx - k12 * cy) - impulseScale * accX;
            float py = -massScale * inv * (k11 * cy - k12 * cx) - impulseScale * accY;
            accX += px;
            accY += py;
            tickX += px;
            tickY += py;
            applyLinear(step, px, py);
            if (!useBias) {
                // The change of the anchors' relative velocity is K times the impulse.
                float jx = accX - warmX;
                float jy = accY - warmY;
                change = Math.max(change, Math.max(Math.abs(k11 * jx + k12 * jy), Math.abs(k12 * jx + k22 * jy)));
            }
        }
        return change;
    }

    /**
     * A fixed joint's point and angle rows solved together, as one 3×3 block (Box2D 2.4's weld): solved
     * one after the other, the two rows fight when an anchor sits far out on a light body (a small
     * circle welded by a 400 px arm diverged, each row undoing the other by more than it fixed).
     *
     * @return the relax pass's change, as {@link #solve} reports it, or −1 when the block is singular
     *     (the rows are then solved one by one)
     */
    private float solveWeld(SolverStep step, boolean useBias, float biasRate, float massScale, float impulseScale) {
        float m = mA + mB;
        float k11 = m + iA * rAy * rAy + iB * rBy * rBy;
        float k12 = -iA * rAy * rAx - iB * rBy * rBx;
        float k13 = -iA * rAy - iB * rBy;
        float k22 = m + iA * rAx * rAx + iB * rBx * rBx;
        float k23 = iA * rAx + iB * rBx;
        float k33 = iA + iB;
        // Cofactors and determinant of K in closed form, as sums of non-negative terms: formed from K's
        // entries they cancel. A 4 px circle welded to a static body by a diagonal 326 px arm has
        // entries near 3,500 and det 0.006: the entries' products lost it to round-off, and the
        // solve flung the circle at 3·10⁵ px/s in its first tick (world fuzzer, seed 2 passive:17).
        float ax = rAx - rBx;
        float ay = rAy - rBy;
        float cross = rAx * rBy - rAy * rBx;
        float ii = iA * iB;
        float c11 = m * k33 + ii * ax * ax;
        float c22 = m * k33 + ii * ay * ay;
        float c12 = ii * ax * ay;
        float c13 = m * (iA * rAy + iB * rBy) + ii * ax * cross;
        float c23 = ii * ay * cross - m * (iA * rAx + iB * rBx);
        float c33 = m * (m + iA * (rAx * rAx + rAy * rAy) + iB * (rBx * rBx + rBy * rBy)) + ii * cross * cross;
        float det = m * (m * k33 + ii * (ax * ax + ay * ay));
        if (!(det > 0f) || !EMath.isFinite(det)) {
            return -1f;
        }
        float cx = relativeVelocityX(step);
        float cy = relativeVelocityY(step);
        float cw = step.getAngularVelocity(ib) - step.getAngularVelocity(ia);
        if (useBias) {
            linearBias(step, biasRate);
            cx += biasX;
            cy += biasY;
            cw += angularBias(step, biasRate);
        }
        float inv = massScale / det;
        float px = -inv * (c11 * cx + c12 * cy + c13 * cw) - impulseScale * accX;
        float py = -inv * (c12 * cx + c22 * cy + c23 * cw) - impulseScale * accY;
        float pw = -inv * (c13 * cx + c23 * cy + c33 * cw) - impulseScale * accAngle;
        accX += px;
        accY += py;
        accAngle += pw;
        tickX += px;
        tickY += py;
        tickAngle += pw;
        applyLinear(step, px, py);
        step.applyAngularImpulse(ia, -pw);
        step.applyAngularImpulse(ib, pw);
        if (useBias) {
            return 0f;
        }
        // The relative velocity K·(acc − warm) the substep's impulse changed beyond its warm start.
        float jx = accX - warmX;
        float jy = accY - warmY;
        float jw = accAngle - warmAngle;
        float dx = Math.abs(k11 * jx + k12 * jy + k13 * jw);
        float dy = Math.abs(k12 * jx + k22 * jy + k23 * jw);
        float dw = Math.abs(k13 * jx + k23 * jy + k33 * jw) * radius;
        return Math.max(dx, Math.max(dy, dw));
    }

    /** The point's position correction, bias rate times error, capped at the joint push speed: into biasX, biasY. */
    private void linearBias(SolverStep step, float biasRate) {
        float bx = biasRate * sepX;
        float by = biasRate * sepY;
        float max = step.getJointPushMaxVelocity();
        float b2 = bx * bx + by * by;
        if (b2 > max * max) {
            float scale = max / EMath.sqrt(b2);
            bx *= scale;
            by *= scale;
        }
        biasX = bx;
        biasY = by;
    }

    /** The angle's correction (rad/s), capped so that the bodies' rims move at most the joint push speed. */
    private float angularBias(SolverStep step, float biasRate) {
        float maxTurn = radius > 0f ? step.getJointPushMaxVelocity() / radius : Float.POSITIVE_INFINITY;
        float bias = biasRate * angleError(step);
        return bias < -maxTurn ? -maxTurn : (bias > maxTurn ? maxTurn : bias);
    }

    /** The angle error now: the tick's start error turned by the bodies' relative rotation since. */
    private float angleError(SolverStep step) {
        float ac = step.getDeltaCos(ia);
        float as = step.getDeltaSin(ia);
        float bc = step.getDeltaCos(ib);
        float bs = step.getDeltaSin(ib);
        float rc = ac * bc + as * bs;
        float rs = ac * bs - as * bc;
        return EMath.atan2(errorSin * rc + errorCos * rs, errorCos * rc - errorSin * rs);
    }

    /**
     * Turns the stored linear impulse with the bodies, by as much of their rotation since it was
     * last applied as keeps its geometric gain below {@link #MAX_TURN_GAIN}.
     *
     * <p>The impulse λ is kept in world axes but applied on arms r that turn with the bodies:
     * re-applied on arms turned by θ, it adds a torque −(r·λ)·θ, a spring on each body's angle
     * that the substeps integrate explicitly and no solve sees. Its gain per substep, h·|r·λ|/I,
     * stays small for loads (at 20 ticks/s: 0.06 for a pendulum released at 90°, 0.22 for a
     * 30-link chain released horizontally). Joints that fight each other (two pins on one body,
     * too far apart to both hold) hold the difference as a stress of thousands of times the
     * bodies' weight: for a 12 px circle pinned at points 14 px and 171 px from its centre, 10 px
     * too far apart, the gain passed the explicit limit of 4 in the first substeps, each
     * substep's torque overshot the last, and the circle was flung to infinity within 7 ticks.
     * Above {@link #MAX_TURN_GAIN}, the impulse turns with the bodies (each weighted by its gain)
     * by the share of their rotation that brings the gain left unturned down to the limit: the
     * fight's stress stays balanced on the arms it was computed for, and the circle settles with
     * a gain near 4. Below the limit nothing changes.
     */
    private void turnImpulse(SolverStep step) {
        float ca = step.getDeltaCos(ia);
        float sa = step.getDeltaSin(ia);
        float cb = step.getDeltaCos(ib);
        float sb = step.getDeltaSin(ib);
        // Each body's rotation since the impulse was applied: now composed with the inverse of then.
        float rca = ca * appliedCosA + sa * appliedSinA;
        float rsa = sa * appliedCosA - ca * appliedSinA;
        float rcb = cb * appliedCosB + sb * appliedSinB;
        float rsb = sb * appliedCosB - cb * appliedSinB;
        appliedCosA = ca;
        appliedSinA = sa;
        appliedCosB = cb;
        appliedSinB = sb;
        arms(step);
        float h = step.getSubstep();
        float gainA = h * iA * Math.abs(rAx * accX + rAy * accY);
        float gainB = h * iB * Math.abs(rBx * accX + rBy * accY);
        float gain = gainA + gainB;
        if (!(gain > MAX_TURN_GAIN)) {
            return;
        }
        // The bodies' rotations weighted by their gains, then the share 1 − limit/gain of it
        // (normalised linear blends: the angles of a substep are small).
        float share = 1f - MAX_TURN_GAIN / gain;
        float c = gainA * rca + gainB * rcb;
        float s = gainA * rsa + gainB * rsb;
        float n = EMath.sqrt(c * c + s * s);
        if (!(n > 0f)) {
            return;
        }
        c = (1f - share) + share * c / n;
        s = share * s / n;
        n = EMath.sqrt(c * c + s * s);
        if (!(n > 0f)) {
            return;
        }
        c /= n;
        s /= n;
        float x = c * accX - s * accY;
        accY = s * accX + c * accY;
        accX = x;
    }

    @Override
    public void finish(SolverStep step) {
        // The rotation in the rest of the last substep: the next tick begins from it.
        if (active) {
            turnImpulse(step);
        }
        float inv = 1f / step.getTimestep();
        force = EMath.length(tickX, tickY) * inv;
        torque = Math.abs(tickAngle) * inv;
    }

    /** x of all linear impulses applied in the last tick (for a hinge that holds this pin). */
    float getTickImpulseX() {
        return tickX;
    }

    /** y of all linear impulses applied in the last tick. */
    float getTickImpulseY() {
        return tickY;
    }

    @Override
    public String toString() {
        return (fixed ? "Joint(fixed, " : "Joint(") + bodyA + ", " + bodyB + ")";
    }
}
