package org.emini.dynamics;

import java.util.Arrays;
import org.emini.math.EMath;
import org.emini.shape.Shape;

/**
 * The solver's flat copy of the moving bodies' state for one tick.
 *
 * <p>Each body occupies {@link #STRIDE} consecutive floats so a contact touches two short runs of
 * memory. Slot 0 is the shared "static" slot: zero velocity and inverse mass, identity motion; every
 * static or frozen body maps to it, which keeps the solver loops free of branches. A kinematic body
 * has a slot of its own with zero inverse mass and inertia and no acceleration: impulses leave its
 * velocity as the application set it, and it moves by that velocity. Only kinematic bodies and the
 * static slot have a zero inverse mass (a shape's mass is finite and positive).
 */
final class SolverBodies {
    static final int STRIDE = 16;
    // Velocity state and inverse mass: what the constraint loops read and write.
    static final int VX = 0;
    static final int VY = 1;
    static final int W = 2;
    static final int IM = 3;
    static final int II = 4;
    // Motion since the start of the tick, used to update contact separations without re-colliding.
    static final int DPX = 5;
    static final int DPY = 6;
    static final int DQC = 7;
    static final int DQS = 8;
    // Pose, written back to the body at the end of the tick.
    static final int X = 9;
    static final int Y = 10;
    static final int C = 11;
    static final int S = 12;
    static final int ANGLE = 13;
    // Constant acceleration over the tick: gravity plus applied force and torque.
    static final int AX = 14;
    static final int AY = 15;

    // Angular acceleration kept apart: it is the only per-body value the stride has no room for.
    float[] alpha = new float[8];
    float[] state = new float[8 * STRIDE];
    // Motion owed by the substep's impacts (x, y, angle per slot): a bounce is taken at the substep's
    // start but happens when the gap closes, so each body still moves with its old velocity until then.
    private float[] owed = new float[8 * 3];
    // Whether any slot owes motion this substep.
    boolean owing;
    Body[] bodies = new Body[8];
    // Each slot's shape: the contact prepare reads it here rather than from the scattered bodies.
    Shape[] shapes = new Shape[8];
    int count;
    // The kinematic bodies among them: the fast-body sweep then looks at moving bodies too.
    int kinematicCount;

    /** Starts a tick with slots 1 to {@code bodyCount} for the bodies that {@link #copyIn} copies. */
    void reset(int bodyCount) {
        int need = bodyCount + 1;
        if (bodies.length < need) {
            int n = Math.max(need, bodies.length * 2);
            bodies = new Body[n];
            shapes = new Shape[n];
            state = new float[n * STRIDE];
            alpha = new float[n];
            owed = new float[n * 3];
        }
        if (owing) {
            // A tick that threw between an impact and the position integration.
            Arrays.fill(owed, 0f);
            owing = false;
        }
        float[] st = state;
        for (int k = 0; k < STRIDE; k++) {
            st[k] = 0f;
        }
        st[DQC] = 1f;
        st[C] = 1f;
        alpha[0] = 0f;
        bodies[0] = null;
        count = need;
        kinematicCount = 0;
    }

    /**
     * Copies the dynamic or kinematic bodies [from, to) of a list in, with the forces applied for this
     * tick: body i to slot i + 1, which becomes its solver index. Each body writes its own slot, so
     * ranges may run on different threads.
     *
     * @return how many of them are kinematic
     */
    int copyIn(Body[] list, int from, int to, float gravityX, float gravityY, long tick) {
        float[] st = state;
        int kinematic = 0;
        for (int i = from; i < to; i++) {
            Body b = list[i];
            int slot = i + 1;
            bodies[slot] = b;
            shapes[slot] = b.getShape();
            if (b.isKinematic()) {
                kinematic++;
            }
            int o = slot * STRIDE;
            copyMotion(b, slot, gravityX, gravityY, tick);
            st[o + DPX] = 0f;
            st[o + DPY] = 0f;
            st[o + DQC] = 1f;
            st[o + DQS] = 0f;
            st[o + X] = b.x;
            st[o + Y] = b.y;
            st[o + C] = b.c;
            st[o + S] = b.s;
            st[o + ANGLE] = b.angle;
            b.solverIndex = slot;
        }
        return kinematic;
    }

    /**
     * Copies a body's mass and forces again, when the application changed them during the solve
     * (from a constraint's prepare, as the manual's jump does).
     */
    void refreshForces(Body b, float gravityX, float gravityY, long tick) {
        int o = b.solverIndex * STRIDE;
        float vx = state[o + VX];
        float vy = state[o + VY];
        float w = state[o + W];
        copyMotion(b, b.solverIndex, gravityX, gravityY, tick);
        state[o + VX] = vx;
        state[o + VY] = vy;
        state[o + W] = w;
    }

    /** Sets a body's velocity in the solve, when the application set it during the solve. */
    void setVelocity(Body b, float vx, float vy, float w) {
        int o = b.solverIndex * STRIDE;
        state[o + VX] = vx;
        state[o + VY] = vy;
        state[o + W] = w;
    }

    /** Adds to a body's velocity in the solve, when the application applied an impulse during the solve. */
    void addVelocity(Body b, float dvx, float dvy, float dw) {
        int o = b.solverIndex * STRIDE;
        state[o + VX] += dvx;
        state[o + VY] += dvy;
        state[o + W] += dw;
    }

    private void copyMotion(Body b, int slot, float gravityX, float gravityY, long tick) {
        float[] st = state;
        int o = slot * STRIDE;
        float im = b.getInverseMass();
        float ii = b.getInverseInertia();
        st[o + VX] = b.vx;
        st[o + VY] = b.vy;
        st[o + W] = b.w;
        st[o + IM] = im;
        st[o + II] = ii;
        // Neither gravity nor forces move a kinematic body.
        boolean kinematic = b.isKinematic();
        float g = b.isAffectedByGravity() && !kinematic ? 1f : 0f;
        // Forces left from a tick that did not simulate the body (it was frozen) do not count.
        float f = b.forceTick == tick && !kinematic ? 1f : 0f;
        st[o + AX] = g * gravityX + f * im * b.forceX;
        st[o + AY] = g * gravityY + f * im * b.forceY;
        alpha[slot] = f * ii * b.torque;
    }

    /** v ← v + h·a for every moving body (symplectic Euler, first half). */
    void integrateVelocities(float h) {
        float[] st = state;
        float[] al = alpha;
        for (int i = 1, o = STRIDE; i < count; i++, o += STRIDE) {
            st[o + VX] += h * st[o + AX];
            st[o + VY] += h * st[o + AY];
            st[o + W] += h * al[i];
        }
    }

    /**
     * x ← x + h·v and q ← q·rot(h·ω) for the moving bodies in slots [from, to) (symplectic Euler,
     * second half); each body's update is its own, so ranges may run on different threads.
     */
    void integratePositions(float h, int from, int to) {
        float[] st = state;
        float[] ow = owing ? owed : null;
        for (int o = from * STRIDE, end = to * STRIDE, i = from; o < end; o += STRIDE, i++) {
            float dx = h * st[o + VX];
            float dy = h * st[o + VY];
            float theta = h * st[o + W];
            if (ow != null) {
                int w = 3 * i;
                dx += ow[w];
                dy += ow[w + 1];
                theta += ow[w + 2];
                ow[w] = 0f;
                ow[w + 1] = 0f;
                ow[w + 2] = 0f;
            }
            st[o + X] += dx;
            st[o + Y] += dy;
            st[o + DPX] += dx;
            st[o + DPY] += dy;
            if (theta == 0f) {
                continue;
            }
            st[o + ANGLE] += theta;
            // Rotation by theta: fifth-order Taylor series for the usual small steps, exact beyond.
            float rc;
            float rs;
            float t2 = theta * theta;
            if (t2 < 0.25f) {
                rc = 1f - 0.5f * t2 * (1f - t2 * (1f / 12f));
                rs = theta * (1f - t2 * (1f / 6f) * (1f - t2 * (1f / 20f)));
            } else {
                rc = EMath.cos(theta);
                rs = EMath.sin(theta);
            }
            rotate(st, o + C, rc, rs);
            rotate(st, o + DQC, rc, rs);
        }
    }

    /** Adds motion a moving body owes this substep (see {@link #owing}); integratePositions takes it. */
    void owe(int slot, float dx, float dy, float dtheta) {
        int w = 3 * slot;
        owed[w] += dx;
        owed[w + 1] += dy;
        owed[w + 2] += dtheta;
        owing = true;
    }

    /** Turns the (cos, sin) pair at st[i], st[i + 1] by (rc, rs) and renormalises it. */
    private static void rotate(float[] st, int i, float rc, float rs) {
        float c = st[i];
        float s = st[i + 1];
        float nc = c * rc - s * rs;
        float ns = s * rc + c * rs;
        float inv = 1f / EMath.sqrt(nc * nc + ns * ns);
        st[i] = nc * inv;
        st[i + 1] = ns * inv;
    }

    /** A body's state in this tick's solve, for error messages. */
    String describe(Body b) {
        int o = b.solverIndex * STRIDE;
        return "position (" + state[o + X] + ", " + state[o + Y] + "), angle " + state[o + ANGLE] + ", velocity ("
            + state[o + VX] + ", " + state[o + VY] + "), angular velocity " + state[o + W];
    }

    /**
     * Copies the state of slots [from, to) back to their bodies, applies the world's per-tick damping
     * (not to kinematic bodies, which keep the velocity set) and clears the forces. Each slot writes
     * its own body, so ranges may run on different threads.
     *
     * @return the first of these slots whose body became non-finite, or 0 (the static slot) for none
     */
    int writeBack(float linearDamped, float angularDamped, int from, int to) {
        float[] st = state;
        int bad = 0;
        for (int i = from, o = from * STRIDE; i < to; i++, o += STRIDE) {
            Body b = bodies[i];
            boolean kinematic = b.isKinematic();
            float linearKeep = kinematic ? 1f : linearDamped;
            float angularKeep = kinematic ? 1f : angularDamped;
            b.x = st[o + X];
            b.y = st[o + Y];
            b.c = st[o + C];
            b.s = st[o + S];
            b.angle = st[o + ANGLE];
            b.vx = st[o + VX] * linearKeep;
            b.vy = st[o + VY] * linearKeep;
            b.w = st[o + W] * angularKeep;
            b.forceX = 0f;
            b.forceY = 0f;
            b.torque = 0f;
            if (bad == 0 && !(EMath.isFinite(b.x + b.y + b.vx + b.vy + b.w + b.c + b.s))) {
                bad = i;
            }
            bodies[i] = null;
            shapes[i] = null;
        }
        return bad;
    }
}
