package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.CopyMapping;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * A spring between an anchor on each body, with a rest length (by default the anchors' distance
 * when the spring is made). The bodies turn freely about the anchors.
 *
 * <p>Without a coefficient the spring is a rigid rod: it keeps the anchors at the rest length,
 * pulling and pushing, solved like a joint. With a coefficient k it follows the spring law
 * F = k·(d − d₀) along the anchor line, the original's meaning, plus an optional damping force
 * c·ḋ; the stiffness can also be given as a natural frequency and damping ratio
 * ({@link #setFrequency}).
 *
 * <p>A spring with a coefficient is not applied as an explicit force, which blows up once the
 * spring's natural frequency times the timestep exceeds 2, but as a soft constraint: the
 * spring-damper is integrated implicitly over each substep, with ω = √(k/m) and
 * ζ = c/(2√(k·m)) for the effective mass m along the anchor line. That is stable at any stiffness.
 * A purely implicit step damps the oscillation numerically (an undamped 10 rad/s spring at 60 ticks
 * per second would lose two thirds of its amplitude in 20 periods), so for springs the substep
 * resolves (ω·h well below 1) the step is centred instead: the implicit midpoint rule. The biased
 * pass solves the spring over half the substep, the positions move with that midpoint velocity,
 * and the other half of the substep's impulse is applied at the start of the next substep. That
 * keeps the energy of an undamped spring, so the closed-form period and decay, and a body resting
 * on a spring reports zero velocity. The blend moves smoothly to the fully implicit step as ω·h
 * approaches 2, where a centred step would ring.
 */
public final class Spring extends TwoBodyConstraint {
    /** Anchors closer than this have no direction: the spring then does nothing (the original's rule). */
    private static final float MIN_LENGTH = 1e-4f;

    /**
     * The rest length that means "the anchors' distance when the spring is made": the original's
     * {@code -1} (any negative rest length given to the constructor does the same).
     */
    public static final float MEASURE_DISTANCE = -1f;

    private float restLength;
    private float coefficient;
    private float damping;
    private float hertz;
    private float dampingRatio;

    private boolean active;
    // Impulse of the current substep's solve along the anchor line (positive pushes B away from A).
    private float acc;
    // The impulse this substep warm-started with, and the inverse effective mass of its last solve.
    private float warm;
    private float lastK;
    // The second half of the last substep's centred spring impulse, applied when the next begins.
    private float pending;
    // Fraction of the substep the biased pass solved the spring over (1/2 centred, 1 implicit).
    private float theta = 1f;
    // The tick's impulse so far, and the part of it counted for the current substep.
    private float tick;
    private float counted;
    private float tension;

    /**
     * Creates a rigid spring whose rest length is the anchors' distance now.
     *
     * @param a the first body
     * @param b the second body
     * @param ax x of the anchor in a's own frame (px)
     * @param ay y of the anchor in a's own frame (px)
     * @param bx x of the anchor in b's own frame (px)
     * @param by y of the anchor in b's own frame (px)
     */
    public Spring(Body a, Body b, float ax, float ay, float bx, float by) {
        super("Spring", a, b, ax, ay, bx, by);
        restLength = getLength();
    }

    /**
     * Creates a rigid spring with a given rest length.
     *
     * @param a the first body
     * @param b the second body
     * @param ax x of the anchor in a's own frame (px)
     * @param ay y of the anchor in a's own frame (px)
     * @param bx x of the anchor in b's own frame (px)
     * @param by y of the anchor in b's own frame (px)
     * @param restLength the rest length (px), &ge; 0; a negative one ({@link #MEASURE_DISTANCE}) means
     *     the anchors' distance now, as in the original engine
     */
    public Spring(Body a, Body b, float ax, float ay, float bx, float by, float restLength) {
        super("Spring", a, b, ax, ay, bx, by);
        Check.finite("Spring", "restLength", restLength);
        this.restLength = restLength < 0f ? getLength() : restLength;
    }

    @Override
    public Spring copy(CopyMapping mapping) {
        Spring copy = new Spring(mapping.body(bodyA), mapping.body(bodyB), localAX, localAY, localBX, localBY, restLength);
        copy.coefficient = coefficient;
        copy.damping = damping;
        copy.hertz = hertz;
        copy.dampingRatio = dampingRatio;
        return copyCommon(copy);
    }

    /**
     * The rest length.
     *
     * @return d₀ (px)
     */
    public float getRestLength() {
        return restLength;
    }

    /**
     * Sets the rest length.
     *
     * @param length d₀ (px), &ge; 0
     */
    public void setRestLength(float length) {
        restLength = Check.nonNegative("Spring.setRestLength", "length", length);
    }

    /**
     * The distance between the anchors where the bodies are now.
     *
     * @return d (px)
     */
    public float getLength() {
        float dx = getAnchorBX() - getAnchorAX();
        float dy = getAnchorBY() - getAnchorAY();
        return EMath.sqrt(dx * dx + dy * dy);
    }

    /**
     * The spring coefficient set with {@link #setCoefficient}.
     *
     * @return k (force per px), 0 when rigid or set as a frequency
     */
    public float getCoefficient() {
        return coefficient;
    }

    /**
     * Makes the spring follow the spring law F = k·(d − d₀), or rigid with k = 0 (the default).
     *
     * @param k the coefficient (mass/s², force per px), &ge; 0
     */
    public void setCoefficient(float k) {
        coefficient = Check.nonNegative("Spring.setCoefficient", "k", k);
        hertz = 0f;
    }

    /**
     * The damping coefficient used with {@link #setCoefficient}.
     *
     * @return c (force per px/s)
     */
    public float getDamping() {
        return damping;
    }

    /**
     * Adds a damping force c·ḋ against the rate the anchors separate or approach, for a spring
     * with a coefficient. Critical damping is 2·√(k·m).
     *
     * @param c the damping coefficient (mass/s, force per px/s), &ge; 0
     */
    public void setDamping(float c) {
        damping = Check.nonNegative("Spring.setDamping", "c", c);
    }

    /**
     * Sets the stiffness as a natural frequency and damping ratio instead of k and c: the spring
     * behaves the same whatever the masses it joins. A frequency of 0 makes the spring rigid.
     *
     * @param hertz the natural frequency (Hz), &ge; 0
     * @param dampingRatio the damping ratio, &ge; 0 (1 is critical)
     */
    public void setFrequency(float hertz, float dampingRatio) {
        this.hertz = Check.nonNegative("Spring.setFrequency", "hertz", hertz);
        this.dampingRatio = Check.nonNegative("Spring.setFrequency", "dampingRatio", dampingRatio);
        coefficient = 0f;
    }

    /**
     * The natural frequency set with {@link #setFrequency}.
     *
     * @return the frequency (Hz), 0 when not set that way
     */
    public float getFrequency() {
        return hertz;
    }

    /**
     * The damping ratio set with {@link #setFrequency}.
     *
     * @return ζ
     */
    public float getDampingRatio() {
        return dampingRatio;
    }

    /**
     * Whether the spring is a rigid rod (no coefficient and no frequency).
     *
     * @return true when rigid
     */
    public boolean isRigid() {
        return coefficient == 0f && hertz == 0f;
    }

    /**
     * The force along the anchor line in the last tick, averaged over it: positive when the spring
     * pulls the bodies together, negative when it pushes them apart.
     *
     * @return the tension (mass·px/s²)
     */
    public float getTension() {
        return tension;
    }

    @Override
    public void prepare(SolverStep step) {
        active = prepareAnchors(step);
        tick = 0f;
    }

    @Override
    public void warmStart(SolverStep step) {
        if (!active) {
            return;
        }
        acc *= substepScale(step);
        warm = acc;
        lastK = 0f;
        float impulse = acc + pending;
        // Unless a solve this substep says otherwise, the spring keeps its last substep's impulse
        // (substeps after dynamic iterations converged only warm start).
        float share = isRigid() ? 1f : theta;
        pending = acc * (1f - share) / share;
        counted = 0f;
        arms(step);
        float len = EMath.sqrt(sepX * sepX + sepY * sepY);
        if (len < MIN_LENGTH) {
            return;
        }
        // The tick's force counts each substep's whole impulse, both parts of a centred one.
        counted = acc / share;
        tick += counted;
        float f = impulse / len;
        applyLinear(step, f * sepX, f * sepY);
    }

    @Override
    public float solve(SolverStep step, boolean useBias) {
        boolean rigid = isRigid();
        if (!active) {
            return 0f;
        }
        if (!rigid && !useBias) {
            // A spring with a coefficient is solved for the whole substep in the biased pass.
            return Math.abs((acc - warm) * lastK);
        }
        arms(step);
        float len = EMath.sqrt(sepX * sepX + sepY * sepY);
        if (len < MIN_LENGTH) {
            return 0f;
        }
        float ux = sepX / len;
        float uy = sepY / len;
        float crA = rAx * uy - rAy * ux;
        float crB = rBx * uy - rBy * ux;
        // K = J M⁻¹ Jᵀ: the inverse effective mass along the anchor line.
        float k = mA + mB + iA * crA * crA + iB * crB * crB;
        if (k <= 0f) {
            return 0f;
        }
        lastK = k;
        float impulse;
        if (rigid) {
            float cdot = relativeVelocityX(step) * ux + relativeVelocityY(step) * uy;
            float bias = 0f;
            if (useBias) {
                float max = step.getJointPushMaxVelocity();
                bias = step.getJointBiasRate() * (len - restLength);
                bias = bias < -max ? -max : (bias > max ? max : bias);
            }
            float massScale = useBias ? step.getJointMassScale() : 1f;
            float impulseScale = useBias ? step.getJointImpulseScale() : 0f;
            impulse = -massScale * (cdot + bias) / k - impulseScale * acc;
            acc += impulse;
            tick += impulse;
            counted += impulse;
        } else {
            impulse = softImpulse(step, k, len, ux, uy);
            acc += impulse;
            // acc is the first part, θ of the substep's impulse; the rest waits for the next substep.
            pending = acc * (1f - theta) / theta;
            tick += acc / theta - counted;
            counted = acc / theta;
        }
        applyLinear(step, impulse * ux, impulse * uy);
        return useBias ? 0f : Math.abs((acc - warm) * k);
    }

    /**
     * The biased pass of a soft spring: Catto's soft constraint for stiffness k and damping c,
     * integrated implicitly over θ·h; θ goes from 1/2 (centred) to 1 (implicit) as ω·h grows to 2.
     */
    private float softImpulse(SolverStep step, float invMass, float len, float ux, float uy) {
        float h = step.getSubstep();
        float k;
        float c;
        if (hertz > 0f) {
            float omega = EMath.TWO_PI * hertz;
            k = omega * omega / invMass;
            c = 2f * dampingRatio * omega / invMass;
        } else {
            k = coefficient;
            c = damping;
        }
        // q = (ω·h/2)², with ω² = k/m.
        float q = 0.25f * k * invMass * h * h;
        theta = q >= 1f ? 1f : 0.5f + 0.5f * q * q;
        float ht = theta * h;
        float d = c + ht * k;
        // γ: the softness (compliance per step), β: position error to velocity.
        float gamma = 1f / (ht * d);
        float beta = k / d;
        float softMass = 1f / (invMass + gamma);
        float cdot = relativeVelocityX(step) * ux + relativeVelocityY(step) * uy;
        return -softMass * (cdot + beta * (len - restLength)) - gamma * softMass * acc;
    }

    @Override
    public void finish(SolverStep step) {
        tension = -tick / step.getTimestep();
        force = Math.abs(tension);
    }

    @Override
    public String toString() {
        return "Spring(" + bodyA + ", " + bodyB + ", rest " + restLength + (isRigid() ? ", rigid)" : ")");
    }
}
