package org.emini.dynamics;

/**
 * The state a {@link Constraint} works on during one tick: the bodies' velocities, their motion
 * since the tick began, the timestep and substep, and the default soft-constraint coefficients.
 *
 * <p>Bodies are addressed by their solver index ({@link #indexOf(Body)}). Static bodies, and
 * bodies frozen outside the simulation area, share index 0: zero velocity, infinite mass, no
 * motion; writes to it are ignored, so constraints need no special cases for them.
 */
public final class SolverStep {
    private final SolverBodies bodies;
    private final Simulation world;
    private float dt;
    private float h;
    private float invH;
    private final Softness jointSoftness = new Softness();
    private float jointPushMax;

    SolverStep(SolverBodies bodies, Simulation world) {
        this.bodies = bodies;
        this.world = world;
    }

    void begin(float dt, float h, SolverSettings settings) {
        this.dt = dt;
        this.h = h;
        this.invH = 1f / h;
        this.jointPushMax = settings.getJointPushMaxVelocity();
        // Twice the contact cap, as stiff as a static contact: a joint held against a static body's
        // contact (a limb caught on a step) would otherwise give way to it.
        float hertz = Math.min(settings.getJointHertz(), 2f * settings.getSubstepHertzRatio() * invH);
        jointSoftness.set(hertz, settings.getJointDampingRatio(), h);
    }

    /**
     * The length of the whole tick.
     *
     * @return the timestep (s)
     */
    public float getTimestep() {
        return dt;
    }

    /**
     * The length of the current substep.
     *
     * @return the substep (s)
     */
    public float getSubstep() {
        return h;
    }

    /**
     * One over the substep.
     *
     * @return 1/h (1/s)
     */
    public float getInverseSubstep() {
        return invH;
    }

    /**
     * The solver index of a body in this tick: 0 for static and frozen bodies.
     *
     * @param body the body
     * @return its index
     * @throws IllegalStateException if the body is not in the world being ticked (a constraint
     *     added to another world than its bodies')
     */
    public int indexOf(Body body) {
        if (body.world != world) {
            throw new IllegalStateException("SolverStep.indexOf: " + body
                + " is not in the world being ticked; add a constraint to the world of its bodies");
        }
        return body.solverIndex;
    }

    /**
     * Inverse mass of a body (0 for index 0).
     *
     * @param index the solver index
     * @return 1/m
     */
    public float getInverseMass(int index) {
        return bodies.state[index * SolverBodies.STRIDE + SolverBodies.IM];
    }

    /**
     * Inverse moment of inertia of a body (0 for index 0 and non-rotating bodies).
     *
     * @param index the solver index
     * @return 1/I
     */
    public float getInverseInertia(int index) {
        return bodies.state[index * SolverBodies.STRIDE + SolverBodies.II];
    }

    /**
     * Current x velocity.
     *
     * @param index the solver index
     * @return vx (px/s)
     */
    public float getVelocityX(int index) {
        return bodies.state[index * SolverBodies.STRIDE + SolverBodies.VX];
    }

    /**
     * Current y velocity.
     *
     * @param index the solver index
     * @return vy (px/s)
     */
    public float getVelocityY(int index) {
        return bodies.state[index * SolverBodies.STRIDE + SolverBodies.VY];
    }

    /**
     * Current angular velocity.
     *
     * @param index the solver index
     * @return ω (rad/s)
     */
    public float getAngularVelocity(int index) {
        return bodies.state[index * SolverBodies.STRIDE + SolverBodies.W];
    }

    /**
     * Sets a body's velocities (ignored for index 0).
     *
     * @param index the solver index
     * @param vx x velocity (px/s)
     * @param vy y velocity (px/s)
     * @param omega angular velocity (rad/s)
     */
    public void setVelocity(int index, float vx, float vy, float omega) {
        if (index == 0) {
            return;
        }
        int o = index * SolverBodies.STRIDE;
        float[] st = bodies.state;
        st[o + SolverBodies.VX] = vx;
        st[o + SolverBodies.VY] = vy;
        st[o + SolverBodies.W] = omega;
    }

    /**
     * Applies an impulse at an arm from the body's origin (ignored for index 0).
     *
     * @param index the solver index
     * @param jx impulse x (mass·px/s)
     * @param jy impulse y (mass·px/s)
     * @param rx arm x (px), in world orientation
     * @param ry arm y (px), in world orientation
     */
    public void applyImpulse(int index, float jx, float jy, float rx, float ry) {
        if (index == 0) {
            return;
        }
        int o = index * SolverBodies.STRIDE;
        float[] st = bodies.state;
        float im = st[o + SolverBodies.IM];
        st[o + SolverBodies.VX] += im * jx;
        st[o + SolverBodies.VY] += im * jy;
        st[o + SolverBodies.W] += st[o + SolverBodies.II] * (rx * jy - ry * jx);
    }

    /**
     * Applies an angular impulse (ignored for index 0).
     *
     * @param index the solver index
     * @param impulse the angular impulse (mass·px²/s)
     */
    public void applyAngularImpulse(int index, float impulse) {
        if (index == 0) {
            return;
        }
        int o = index * SolverBodies.STRIDE;
        bodies.state[o + SolverBodies.W] += bodies.state[o + SolverBodies.II] * impulse;
    }

    /**
     * Displacement in x since the tick began (0 for index 0).
     *
     * @param index the solver index
     * @return Δx (px)
     */
    public float getDeltaX(int index) {
        return bodies.state[index * SolverBodies.STRIDE + SolverBodies.DPX];
    }

    /**
     * Displacement in y since the tick began (0 for index 0).
     *
     * @param index the solver index
     * @return Δy (px)
     */
    public float getDeltaY(int index) {
        return bodies.state[index * SolverBodies.STRIDE + SolverBodies.DPY];
    }

    /**
     * Cosine of the rotation since the tick began (1 for index 0).
     *
     * @param index the solver index
     * @return cos Δθ
     */
    public float getDeltaCos(int index) {
        return bodies.state[index * SolverBodies.STRIDE + SolverBodies.DQC];
    }

    /**
     * Sine of the rotation since the tick began (0 for index 0).
     *
     * @param index the solver index
     * @return sin Δθ
     */
    public float getDeltaSin(int index) {
        return bodies.state[index * SolverBodies.STRIDE + SolverBodies.DQS];
    }

    /**
     * A body's current angle, static bodies included.
     *
     * @param body the body
     * @return the angle (rad)
     */
    public float getAngle(Body body) {
        int i = body.solverIndex;
        return i == 0 ? body.angle : bodies.state[i * SolverBodies.STRIDE + SolverBodies.ANGLE];
    }

    /**
     * A body's current x position (its origin), static bodies included.
     *
     * @param body the body
     * @return x (px)
     */
    public float getPositionX(Body body) {
        int i = body.solverIndex;
        return i == 0 ? body.x : bodies.state[i * SolverBodies.STRIDE + SolverBodies.X];
    }

    /**
     * A body's current y position (its origin), static bodies included.
     *
     * @param body the body
     * @return y (px)
     */
    public float getPositionY(Body body) {
        int i = body.solverIndex;
        return i == 0 ? body.y : bodies.state[i * SolverBodies.STRIDE + SolverBodies.Y];
    }

    /**
     * The fastest a joint's position correction may move its anchors toward each other
     * ({@link SolverSettings#getJointPushMaxVelocity()}): constraints clamp their bias velocity
     * (bias rate times error) to it, angular ones to it divided by their bodies' radius.
     *
     * @return the speed (px/s)
     */
    public float getJointPushMaxVelocity() {
        return jointPushMax;
    }

    /**
     * Position correction rate of the default joint softness for this substep.
     *
     * @return the bias rate (1/s)
     */
    public float getJointBiasRate() {
        return jointSoftness.biasRate;
    }

    /**
     * Mass scale of the default joint softness for this substep.
     *
     * @return the mass scale
     */
    public float getJointMassScale() {
        return jointSoftness.massScale;
    }

    /**
     * Impulse scale of the default joint softness for this substep.
     *
     * @return the impulse scale
     */
    public float getJointImpulseScale() {
        return jointSoftness.impulseScale;
    }

    /**
     * Soft-constraint coefficients for a spring-damper over the current substep, written to
     * out[0] = bias rate (1/s), out[1] = mass scale, out[2] = impulse scale. The result is stable
     * for any stiffness, unlike an explicit spring force.
     *
     * @param hertz the natural frequency (Hz); 0 gives a rigid constraint without bias
     * @param dampingRatio the damping ratio (1 = critical)
     * @param out an array of at least 3 elements
     */
    public void soften(float hertz, float dampingRatio, float[] out) {
        Softness.coefficients(hertz, dampingRatio, h, out);
    }
}
