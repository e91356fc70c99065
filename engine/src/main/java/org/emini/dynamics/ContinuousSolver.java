package org.emini.dynamics;

import static org.emini.dynamics.SolverBodies.ANGLE;
import static org.emini.dynamics.SolverBodies.C;
import static org.emini.dynamics.SolverBodies.DPX;
import static org.emini.dynamics.SolverBodies.DPY;
import static org.emini.dynamics.SolverBodies.S;
import static org.emini.dynamics.SolverBodies.STRIDE;
import static org.emini.dynamics.SolverBodies.VX;
import static org.emini.dynamics.SolverBodies.VY;
import static org.emini.dynamics.SolverBodies.W;
import static org.emini.dynamics.SolverBodies.X;
import static org.emini.dynamics.SolverBodies.Y;

import org.emini.collision.BroadPhase;
import org.emini.collision.QueryCallback;
import org.emini.collision.Segment;
import org.emini.collision.TimeOfImpact;
import org.emini.math.EMath;
import org.emini.shape.Shape;

/**
 * The fast-body pass: after the solver, a dynamic body that moved more than half its smallest
 * extent in the tick is swept from its start pose to its end pose against static and kinematic
 * bodies and the landscape (and, for bullets, against dynamic bodies too, taken at their end poses).
 * If it would have touched one on the way, it is put back at the time of impact; its velocity is
 * kept, so the next tick's speculative contact resolves the collision. Speculative contacts alone
 * stop most fast bodies; this pass catches the rest, notably fast-spinning bodies with long arms.
 *
 * <p>A moving kinematic body is swept against in its own frame: the mover's motion relative to it
 * over the tick, so a body the kinematic one carries or pushes along (no relative motion) is not
 * put back, and a body it hits is put back touching it where it ends the tick. Kinematic bodies are
 * not swept themselves: nothing they pass through stops them, and a dynamic body they hit is caught
 * by the pair's speculative contact, whose margin grows with both bodies' speeds.
 */
final class ContinuousSolver implements QueryCallback {
    // A slot's mark: nothing to do, a sweep, or a state outside the finite range.
    private static final byte STILL = 0;
    private static final byte FAST = 1;
    private static final byte NOT_FINITE = 2;

    private final Simulation world;
    private final TimeOfImpact toi = new TimeOfImpact();
    private final float[] box = new float[4];
    private final float[] box2 = new float[4];
    // State of the current sweep, read by the broadphase callback.
    private Body moving;
    private float x0;
    private float y0;
    private float a0;
    private float x1;
    private float y1;
    private float a1;
    // The moving body's centre of mass at the start and the end of the tick: its side of an unfaced segment.
    private float cx0;
    private float cy0;
    private float cx1;
    private float cy1;
    private float target;
    private float fraction;
    private float[] state;
    // When the earliest hit is with a moving kinematic body: the mover's pose at that time, put
    // relative to the kinematic body's end pose.
    private boolean kinematicHit;
    private float hitX;
    private float hitY;
    private float hitAngle;
    // The multi-shape bodies this sweep has met: the broadphase reports one once per part near it.
    private Body[] met = new Body[4];
    private int metCount;

    private final LandscapeSweep segments = new LandscapeSweep();
    // Per slot, what mark() found.
    private byte[] marks = new byte[8];

    ContinuousSolver(Simulation world) {
        this.world = world;
    }

    /** Makes room for a mark per slot of the coming solve; before {@link #mark}. */
    void begin(int slotCount) {
        if (marks.length < slotCount) {
            marks = new byte[Math.max(slotCount, 2 * marks.length)];
        }
    }

    /**
     * Marks which of slots [from, to) moved far enough in the tick to be swept, and which left the
     * finite range. Each slot is its own and a sweep changes only its own slot's pose, so ranges
     * may run on different threads, before {@link #solve}.
     */
    void mark(SolverBodies sb, int from, int to) {
        float[] st = sb.state;
        byte[] m = marks;
        for (int i = from, o = from * STRIDE; i < to; i++, o += STRIDE) {
            Body b = sb.bodies[i];
            Shape shape = sb.shapes[i];
            float da = st[o + ANGLE] - b.angle;
            float travel = Math.abs(st[o + DPX]) + Math.abs(st[o + DPY]) + Math.abs(da) * shape.getBoundingRadius();
            if (!EMath.isFinite(travel + st[o + X] + st[o + Y] + st[o + VX] + st[o + VY] + st[o + W])) {
                m[i] = NOT_FINITE;
            } else if (b.isKinematic() || travel <= 2f * TimeOfImpact.coreRadius(shape)) {
                m[i] = STILL;
            } else {
                m[i] = FAST;
            }
        }
    }

    /**
     * Moves each fast body ({@link #mark}) back to its first time of impact with a static body (a
     * bullet: any body) or the landscape, in slot order.
     *
     * @return null, or the first body whose new state is not finite or whose swept box overflows
     *     (nothing can be swept for it; the tick stops with an error naming it)
     */
    Body solve(SolverBodies sb, BroadPhase broadPhase, float target) {
        this.target = target;
        float[] st = sb.state;
        state = st;
        byte[] m = marks;
        for (int i = 1, o = STRIDE; i < sb.count; i++, o += STRIDE) {
            if (m[i] == STILL) {
                continue;
            }
            Body b = sb.bodies[i];
            if (m[i] == NOT_FINITE) {
                return escaped(b);
            }
            Shape shape = sb.shapes[i];
            float dx = st[o + DPX];
            float dy = st[o + DPY];
            float da = st[o + ANGLE] - b.angle;
            moving = b;
            x1 = st[o + X];
            y1 = st[o + Y];
            a1 = st[o + ANGLE];
            x0 = x1 - dx;
            y0 = y1 - dy;
            a0 = b.angle;
            float lx = shape.getCentroidX();
            float ly = shape.getCentroidY();
            cx0 = x0 + b.c * lx - b.s * ly;
            cy0 = y0 + b.s * lx + b.c * ly;
            cx1 = x1 + st[o + C] * lx - st[o + S] * ly;
            cy1 = y1 + st[o + S] * lx + st[o + C] * ly;
            fraction = 1f;
            kinematicHit = false;
            metCount = 0;
            shape.computeAabb(x0, y0, b.c, b.s, box);
            shape.computeAabb(x1, y1, st[o + C], st[o + S], box2);
            float minX = Math.min(box[0], box2[0]);
            float minY = Math.min(box[1], box2[1]);
            float maxX = Math.max(box[2], box2[2]);
            float maxY = Math.max(box[3], box2[3]);
            if (!EMath.isFinite(minX + minY + maxX + maxY)) {
                // Finite poses whose swept box overflows: no query can place it.
                return escaped(b);
            }
            // Only bullets sweep against dynamic bodies; the others search the static tree alone, and
            // the moving proxies' too when kinematic bodies are among them.
            if (b.isBullet() || sb.kinematicCount > 0) {
                broadPhase.query(minX, minY, maxX, maxY, this);
            } else {
                broadPhase.queryStatic(minX, minY, maxX, maxY, this);
            }
            segments.sweep(minX, minY, maxX, maxY);
            if (kinematicHit) {
                st[o + X] = hitX;
                st[o + Y] = hitY;
                st[o + ANGLE] = hitAngle;
                st[o + C] = EMath.cos(hitAngle);
                st[o + S] = EMath.sin(hitAngle);
            } else if (fraction < 1f) {
                float a = a0 + fraction * da;
                st[o + X] = x0 + fraction * dx;
                st[o + Y] = y0 + fraction * dy;
                st[o + ANGLE] = a;
                st[o + C] = EMath.cos(a);
                st[o + S] = EMath.sin(a);
            }
        }
        moving = null;
        state = null;
        java.util.Arrays.fill(met, 0, metCount, null);
        return null;
    }

    private Body escaped(Body b) {
        moving = null;
        state = null;
        java.util.Arrays.fill(met, 0, metCount, null);
        return b;
    }

    @Override
    public boolean reportProxy(int proxyId) {
        Body other = world.bodyOfProxy(proxyId);
        if (other == moving || !world.shouldCollide(moving, other) || alreadyMet(other)) {
            return true;
        }
        // Bullets sweep against everything; other bodies only against static and kinematic ones.
        if (other.isDynamic() && !moving.isBullet()) {
            return true;
        }
        float ox = other.x;
        float oy = other.y;
        float oc = other.c;
        float os = other.s;
        if (other.solverIndex != 0) {
            if (other.isKinematic()) {
                sweepAgainstKinematic(other);
                return true;
            }
            // A moving obstacle is taken at its end pose.
            int o = other.solverIndex * STRIDE;
            ox = state[o + X];
            oy = state[o + Y];
            oc = state[o + C];
            os = state[o + S];
        }
        float t = toi.solve(moving.getShape(), x0, y0, a0, x1, y1, a1, other.getShape(), ox, oy, oc, os, target);
        if (t < fraction) {
            fraction = t;
            kinematicHit = false;
        }
        return true;
    }

    /** Whether the sweep has met a multi-shape body already (through another part); notes it if not. */
    private boolean alreadyMet(Body other) {
        if (other.partKeys.length == 1) {
            return false;
        }
        for (int i = 0; i < metCount; i++) {
            if (met[i] == other) {
                return true;
            }
        }
        if (metCount == met.length) {
            met = java.util.Arrays.copyOf(met, 2 * metCount);
        }
        met[metCount++] = other;
        return false;
    }

    /**
     * The sweep in a moving kinematic body's frame: the obstacle held at its start pose K0, the
     * mover from its start pose to its end pose seen from the obstacle's end pose K1 (K0·K1⁻¹·B1).
     * A hit puts the mover at its pose of that time in the obstacle's frame, carried to K1.
     */
    private void sweepAgainstKinematic(Body other) {
        int o = other.solverIndex * STRIDE;
        float kx0 = other.x;
        float ky0 = other.y;
        float kc0 = other.c;
        float ks0 = other.s;
        float kx1 = state[o + X];
        float ky1 = state[o + Y];
        float kc1 = state[o + C];
        float ks1 = state[o + S];
        float turn = state[o + ANGLE] - other.angle;
        // Rotation by −turn: from the end frame back to the start frame.
        float bc = kc0 * kc1 + ks0 * ks1;
        float bs = ks0 * kc1 - kc0 * ks1;
        float ex = x1 - kx1;
        float ey = y1 - ky1;
        float rx1 = kx0 + bc * ex - bs * ey;
        float ry1 = ky0 + bs * ex + bc * ey;
        float ra1 = a1 - turn;
        float t = toi.solve(moving.getShape(), x0, y0, a0, rx1, ry1, ra1, other.getShape(), kx0, ky0, kc0, ks0, target);
        if (t < fraction) {
            fraction = t;
            kinematicHit = true;
            // The pose at t relative to K0, carried to K1 (rotation by +turn about the obstacle).
            float px = x0 + t * (rx1 - x0) - kx0;
            float py = y0 + t * (ry1 - y0) - ky0;
            hitX = kx1 + bc * px + bs * py;
            hitY = ky1 - bs * px + bc * py;
            hitAngle = a0 + t * (ra1 - a0) + turn;
        }
    }

    /**
     * The sweep against the landscape: the segments whose boxes meet the swept box and that the
     * body would get through by the end pose, its side point crossing the segment's line or its shape
     * sinking deeper than its core radius (what the contacts would not undo). Not the segments a
     * body merely slides onto along a chain, nor a faced segment whose open side it starts on (it
     * may pass), nor zero-length ones (they stop nothing).
     */
    private final class LandscapeSweep implements QueryCallback {
        private final Segment segment = new Segment();
        private Landscape landscape;

        void sweep(float minX, float minY, float maxX, float maxY) {
            landscape = world.getLandscape();
            if (landscape.getSegmentCount() > 0) {
                landscape.query(minX, minY, maxX, maxY, this);
            }
            landscape = null;
        }

        @Override
        public boolean reportProxy(int slot) {
            landscape.fill(slot, segment);
            Shape shape = moving.getShape();
            float ex = segment.x2 - segment.x1;
            float ey = segment.y2 - segment.y1;
            if (ex * ex + ey * ey < 1e-12f) {
                return true;
            }
            // (end − start) × (side point − start): negative on the left side, which face 1 blocks;
            // as in the narrowphase, the origin decides for a faced segment, the centre of mass for
            // an unfaced one, and a body exactly on the line is blocked.
            boolean faced = segment.face != Segment.FACE_NONE;
            float before = faced ? ex * (y0 - segment.y1) - ey * (x0 - segment.x1)
                : ex * (cy0 - segment.y1) - ey * (cx0 - segment.x1);
            if (segment.face != Segment.FACE_NONE && before != 0f
                    && (segment.face == Segment.FACE_LEFT) != (before < 0f)) {
                return true;
            }
            float c1 = state[moving.solverIndex * SolverBodies.STRIDE + C];
            float s1 = state[moving.solverIndex * SolverBodies.STRIDE + S];
            float after = faced ? ex * (y1 - segment.y1) - ey * (x1 - segment.x1)
                : ex * (cy1 - segment.y1) - ey * (cx1 - segment.x1);
            boolean crossed = (before < 0f) != (after < 0f);
            if (!crossed && TimeOfImpact.segmentSeparation(shape, x1, y1, c1, s1, segment)
                    > -Math.max(TimeOfImpact.coreRadius(shape), target)) {
                return true;
            }
            float t = toi.solveSegment(shape, x0, y0, a0, x1, y1, a1, segment, target);
            if (t < fraction) {
                fraction = t;
                kinematicHit = false;
            }
            return true;
        }
    }
}
