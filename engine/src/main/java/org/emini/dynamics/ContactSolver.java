package org.emini.dynamics;

import org.emini.shape.Circle;
import org.emini.shape.Shape;

import static org.emini.dynamics.SolverBodies.AX;
import static org.emini.dynamics.SolverBodies.AY;
import static org.emini.dynamics.SolverBodies.DPX;
import static org.emini.dynamics.SolverBodies.DPY;
import static org.emini.dynamics.SolverBodies.DQC;
import static org.emini.dynamics.SolverBodies.DQS;
import static org.emini.dynamics.SolverBodies.II;
import static org.emini.dynamics.SolverBodies.IM;
import static org.emini.dynamics.SolverBodies.STRIDE;
import static org.emini.dynamics.SolverBodies.VX;
import static org.emini.dynamics.SolverBodies.VY;
import static org.emini.dynamics.SolverBodies.W;
import static org.emini.dynamics.SolverBodies.X;
import static org.emini.dynamics.SolverBodies.Y;

import org.emini.internal.WorkerPool;

/**
 * Soft-step contact constraints: the design of Box2D v3 (Catto's "solver2d" study), on flat arrays.
 *
 * <p>Per substep: warm start, one biased solve with soft (spring-damper) contacts, position
 * integration, one unbiased relax pass (then more, over the contacts of bodies an impact moved:
 * {@link #relaxHot}). Contacts are not re-collided per substep; their separation is
 * updated from the bodies' motion since the tick started. Elastic impacts are pairwise collisions
 * at the start of the substep in which they close ({@link #impacts}). The relax pass removes the
 * velocity the push-out created, so overlap is resolved without adding energy.
 *
 * <p>Layout: each constraint is {@link #CS} floats (shared data then two point blocks of
 * {@link #PS} floats) plus {@link #CI} ints; a constraint's whole state sits in one or two cache
 * lines.
 */
final class ContactSolver {
    // Per-constraint floats.
    static final int NX = 0;
    static final int NY = 1;
    static final int FRICTION = 2;
    static final int RESTITUTION = 3;
    private static final int BIAS_RATE = 4;
    private static final int MASS_SCALE = 5;
    private static final int IMPULSE_SCALE = 6;
    // Inverse of the 2×2 normal mass matrix of a two-point manifold; BLOCK is 1 when well conditioned.
    static final int BLOCK = 7;
    static final int K11 = 8;
    static final int K12 = 9;
    static final int K22 = 10;
    // A circle's contact point does not turn with the circle: the separation follows the circle's
    // centre, the point's arm minus K times the normal (K 0 for a body without a circle there).
    static final int CIRCLE_A = 11;
    static final int CIRCLE_B = 12;
    // The most the common impulse point may move from the tick's contact point: a fifth of the
    // smaller part's bounding radius, so that the tick's effective masses still hold for the moved
    // arms (unbounded, a fast pair's arms grew by tens of pixels and the solve diverged). 0 unless
    // both bodies are dynamic and in a cluster that touches no static or kinematic body (level 0):
    // only there is angular momentum conserved, and moving the point cost resting piles 12%.
    static final int SHIFT = 13;
    static final int P0 = 14;
    // Per-point floats, relative to the point block.
    static final int RAX = 0;
    static final int RAY = 1;
    static final int RBX = 2;
    static final int RBY = 3;
    static final int BASE_SEP = 4;
    static final int NMASS = 5;
    static final int TMASS = 6;
    static final int NIMP = 7;
    static final int TIMP = 8;
    static final int MAXIMP = 9;
    static final int RELVEL = 10;
    // Inverse effective normal mass (1 / NMASS, or 0): impulse to relative speed without a division.
    private static final int KN = 11;
    static final int PS = 12;
    static final int CS = P0 + 2 * PS;
    // Per-constraint ints.
    static final int BODY_A = 0;
    static final int BODY_B = 1;
    static final int POINTS = 2;
    static final int CI = 3;

    private float[] f = new float[16 * CS];
    private int[] n = new int[16 * CI];
    private Contact[] contacts = new Contact[16];
    // Per slot: its contact's index in the narrowphase's list.
    private int[] contactOf = new int[16];
    private int count;
    // The contacts of the narrowphase's list this tick's slots were prepared from.
    private int preparedCount;

    private final ElasticImpacts impacts = new ElasticImpacts();

    /** Colours of the graph colouring; contacts that find none left go to the overflow group after them. */
    static final int COLOURS = 256;
    /** Longs per body of the colouring's bit set: one bit per colour. */
    private static final int WORDS = COLOURS / 64;
    // Slots of colour c: colourStart[c] to colourStart[c + 1] − 1; the overflow group is colour COLOURS.
    private final int[] colourStart = new int[COLOURS + 2];
    private final int[] colourFill = new int[COLOURS + 1];
    // Per moving body: the colours its contacts took this tick, one bit each.
    private long[] usedColours = new long[16];
    // The contact graph's breadth-first search (see levels): per body its level, where its
    // neighbours start in adjacency, and the search's queue.
    private int[] level = new int[16];
    private int[] adjacencyStart = new int[17];
    private int[] adjacency = new int[32];
    private int[] queue = new int[16];
    // Per contact of the narrowphase's list: its slot, or −1 when it is not solved.
    private int[] slotOf = new int[16];
    // The colouring's input last tick: when this tick's is the same, so are slotOf and colourStart.
    private final ContactGraphKey graph = new ContactGraphKey();
    // The small islands' slots (after the colours') and their runs, when this colouring laid them out.
    private final SolveIslands islands = new SolveIslands();
    // Whether the colouring was made for threads, and colourings left before islands are looked for again.
    private boolean colouredForThreads;
    private int islandsSkipped;
    private static final int ISLAND_SKIPS = 15;
    /** False: colour every tick afresh (tests compare the two). */
    boolean keepColouring = true;
    /** Colourings computed, for tests. */
    int colourings;

    /**
     * Dynamic iterations' convergence measure, set by a tracked relax pass: the largest change of a
     * point's relative velocity (px/s) that the substep's impulses made beyond its warm start, or
     * infinity when a speculative point may close before the tick ends. Below the tolerance, later
     * substeps may repeat the warm start alone.
     */
    float lastChange;

    // Dynamic iterations only: each point's normal and tangent impulse as warm-started this substep.
    private float[] warm = new float[0];

    // Per solver body: the relax pass that last changed its velocity by more than the hot tolerance.
    private int[] hot = new int[16];
    // Relax passes so far; passes are told apart by this number, so stamps never need clearing.
    private int pass;
    private boolean anyHot;
    private final HotContacts hotContacts = new HotContacts();

    /**
     * The fewest contacts of a colour worth a thread of their own. A contact costs about 40 ns a pass
     * and a split, while the other thread spins, under a microsecond, so 32 contacts pay for it. The
     * level colouring makes many colours of 100 to 250 contacts and a few small top ones (ten 20-row
     * pyramids): at 128 most ran on one thread, and two threads gave 1.13 times the speed of one; at
     * 48, 1.3 to 1.4, with the seven colours under 96 contacts (7% of them, 140 µs a tick) on one
     * thread; at 32, 3% faster than at 48 (16: no faster).
     */
    static final int MIN_PART = 32;
    /** Per-part results sit this many elements apart, so that threads do not share a cache line. */
    private static final int PAD = 16;
    private WorkerPool pool;
    /** The fewest contacts given to a thread (MIN_PART; tests lower it to split every colour). */
    int minPart = MIN_PART;
    private float[] workerChange = new float[PAD];
    private int[] workerHot = new int[PAD];
    private float[] workerLoad = new float[PAD];
    // The pass that forColours runs, as the range tasks read it.
    private SubstepContext passContext;
    private SolverBodies passBodies;
    private boolean passUseBias;
    private boolean passHotOnly;
    private int passPrevious;
    private int passCurrent;
    private final WorkerPool.RangeTask passTask = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            passRange(part, from, to);
        }
    };
    // The prepare that prepareTask runs.
    private Contact[] prepareContacts;
    private Softness prepareSoft;
    private Softness prepareStaticSoft;
    private float prepareCondition;
    private float prepareImpulseStep;
    private final WorkerPool.RangeTask prepareTask = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            prepareRange(part, from, to);
        }
    };
    // The task that islandRuns runs over each thread's run of small islands.
    private WorkerPool.RangeTask runTask;
    private final WorkerPool.RangeTask islandRuns = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            for (int k = from; k < to; k++) {
                runTask.run(part, islands.runStart(k), islands.runStart(k + 1));
            }
        }
    };
    private final WorkerPool.RangeTask warmTask = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            warmRange(from, to);
        }
    };
    private final WorkerPool.RangeTask storeTask = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            storeRange(from, to);
        }
    };

    /**
     * Shares the passes with a pool's threads, colour by colour, or solves on the calling thread alone
     * (null). The results are the same either way.
     */
    void setPool(WorkerPool workers) {
        pool = workers;
        // The island runs were split for the old thread count: colour afresh.
        graph.forget();
        int size = PAD * (workers == null ? 1 : workers.getThreadCount());
        if (workerChange.length < size) {
            workerChange = new float[size];
            workerHot = new int[size];
            workerLoad = new float[size];
        }
    }

    /**
     * Builds the constraints of all touching contacts from the poses at the start of the tick.
     * Softness is set per constraint: contacts with a static body use the stiffer setting.
     */
    void prepare(Contact[] all, boolean[] noPoints, int contactCount, SolverBodies bodies, Softness soft, Softness staticSoft,
            float maxCondition, float impulseStep) {
        ensure(contactCount);
        preparedCount = contactCount;
        colour(all, noPoints, contactCount, bodies);
        hotContacts.slotsChanged();
        prepareContacts = all;
        passBodies = bodies;
        prepareSoft = soft;
        prepareStaticSoft = staticSoft;
        prepareCondition = maxCondition;
        prepareImpulseStep = impulseStep;
        for (int w = 0; w < workerLoad.length; w += PAD) {
            workerLoad[w] = 0f;
        }
        if (pool != null) {
            pool.run(prepareTask, 0, contactCount, minPart);
        } else {
            prepareRange(0, 0, contactCount);
        }
        prepareContacts = null;
        impacts.collect(f, count);
    }

    /** Builds the constraints of contacts [from, to) of the narrowphase's list (each writes only its slot). */
    private void prepareRange(int worker, int from, int to) {
        Contact[] all = prepareContacts;
        float[] st = passBodies.state;
        Softness soft = prepareSoft;
        Softness staticSoft = prepareStaticSoft;
        float maxCondition = prepareCondition;
        float impulseStep = prepareImpulseStep;
        float load = 0f;
        for (int ci = from; ci < to; ci++) {
            int k = slotOf[ci];
            if (k < 0) {
                continue;
            }
            Contact c = all[ci];
            // The slots, positions and shapes of bodies that have a slot come from the graph key and
            // the solver's copies, not from the body objects, which lie scattered in memory.
            int ia = graph.first(ci);
            int second = graph.second(ci);
            int ib = second >= 0 ? second : 0;
            int oa = ia * STRIDE;
            int ob = ib * STRIDE;
            Body a = c.bodyA;
            // A landscape contact has no body B: the static slot, anchored where A is, so that its
            // arm is A's and no large world coordinate enters the separation update.
            Body b = c.bodyB != null ? c.bodyB : a;
            Shape shapeA = ia != 0 ? passBodies.shapes[ia] : a.getShape();
            Shape shapeB = ib != 0 ? passBodies.shapes[ib] : b.getShape();
            float ax = ia != 0 ? st[oa + X] : a.x;
            float ay = ia != 0 ? st[oa + Y] : a.y;
            float bx = c.bodyB == null ? ax : (ib != 0 ? st[ob + X] : b.x);
            float by = c.bodyB == null ? ay : (ib != 0 ? st[ob + Y] : b.y);
            contacts[k] = c;
            contactOf[k] = ci;
            int fo = k * CS;
            int io = k * CI;
            n[io + BODY_A] = ia;
            n[io + BODY_B] = ib;
            n[io + POINTS] = c.pointCount;
            float nx = c.normalX;
            float ny = c.normalY;
            f[fo + NX] = nx;
            f[fo + NY] = ny;
            f[fo + FRICTION] = c.friction;
            f[fo + RESTITUTION] = c.restitution;
            float mA = st[oa + IM];
            float iA = st[oa + II];
            float mB = st[ob + IM];
            float iB = st[ob + II];
            soften(fo, mA == 0f || mB == 0f, soft, staticSoft);
            // A dynamic body pressed onto another by gravity and forces loads their contact with its
            // weight: the acceleration that weight gives the pair along the normal. Only when the
            // contact carried at least a quarter of it in the last substep: a pinned or hanging body
            // puts its weight on its joints, not on what it touches.
            if (mA != 0f && mB != 0f && c.pointCount > 0) {
                float pushA = st[oa + AX] * nx + st[oa + AY] * ny;
                float pushB = -(st[ob + AX] * nx + st[ob + AY] * ny);
                float sum = mA + mB;
                // Compared as products first: most pairs cannot raise the load, and pay no division.
                boolean raisesA = pushA * sum > load * mA;
                boolean raisesB = pushB * sum > load * mB;
                if (raisesA || raisesB) {
                    float impulse = c.pointCount == 2 ? c.normalImpulse0 + c.normalImpulse1 : c.normalImpulse0;
                    if (raisesA && 4f * impulse * mA >= pushA * impulseStep) {
                        load = Math.max(load, pushA * sum / mA);
                    }
                    if (raisesB && 4f * impulse * mB >= pushB * impulseStep) {
                        load = Math.max(load, pushB * sum / mB);
                    }
                }
            }
            float vax = st[oa + VX];
            float vay = st[oa + VY];
            float wa = st[oa + W];
            float vbx = st[ob + VX];
            float vby = st[ob + VY];
            float wb = st[ob + W];
            // The point lies midway, half the separation beyond each surface (a circle has one point).
            // Against a circle it lies on the circle's surface instead, for both bodies: rolling then
            // ties v to ω r, where the midway point tied it to ω (r − overlap / 2) (a disc rolling down
            // a slope lagged its closed form by 0.017 px/s), and both bodies take the impulse at one
            // point, or friction would turn the world (a rod striking a ball across a 40 px gap
            // created 330 units of angular momentum when only the ball's arm was moved). Two
            // circles keep the midpoint unless one of them cannot move.
            float half = c.pointCount > 0 ? 0.5f * c.separation0 : 0f;
            float rA = circleRadius(shapeA, c.partA);
            float rB = c.bodyB != null ? circleRadius(shapeB, c.partB) : 0f;
            float shift = 0f;
            if (rA > 0f && (rB == 0f || mB == 0f)) {
                shift = -half;
            } else if (rB > 0f && (rA == 0f || mA == 0f)) {
                shift = half;
            }
            // A circle's separation does not depend on its turning: its arm's projection on the
            // normal, which the separation update adds back as the arm turns.
            float kA = rA > 0f ? rA + half + shift : 0f;
            float kB = rB > 0f ? -(rB + half - shift) : 0f;
            f[fo + CIRCLE_A] = kA;
            f[fo + CIRCLE_B] = kB;
            f[fo + SHIFT] = mA != 0f && mB != 0f && c.bodyB != null && level[ia] == 0 && level[ib] == 0
                ? 0.2f * Math.min(ContactManager.part(shapeA, c.partA).getBoundingRadius(),
                    ContactManager.part(shapeB, c.partB).getBoundingRadius())
                : 0f;
            for (int p = 0; p < c.pointCount; p++) {
                int po = fo + P0 + p * PS;
                float cpx = c.pointX(p);
                float cpy = c.pointY(p);
                float rax = cpx - ax;
                float ray = cpy - ay;
                float rbx = cpx - bx;
                float rby = cpy - by;
                if (shift != 0f) {
                    rax += shift * nx;
                    ray += shift * ny;
                    rbx += shift * nx;
                    rby += shift * ny;
                }
                f[po + RAX] = rax;
                f[po + RAY] = ray;
                f[po + RBX] = rbx;
                f[po + RBY] = rby;
                f[po + BASE_SEP] = c.separation(p) - ((rbx - rax) * nx + (rby - ray) * ny) + kB - kA;
                float rna = rax * ny - ray * nx;
                float rnb = rbx * ny - rby * nx;
                float kn = mA + mB + iA * rna * rna + iB * rnb * rnb;
                f[po + NMASS] = kn > 0f ? 1f / kn : 0f;
                f[po + KN] = kn > 0f ? kn : 0f;
                // Tangent t = (−ny, nx).
                float rta = rax * nx + ray * ny;
                float rtb = rbx * nx + rby * ny;
                float kt = mA + mB + iA * rta * rta + iB * rtb * rtb;
                f[po + TMASS] = kt > 0f ? 1f / kt : 0f;
                f[po + NIMP] = c.normalImpulse(p);
                f[po + TIMP] = c.tangentImpulse(p);
                f[po + MAXIMP] = 0f;
                float dvx = vbx - wb * rby - vax + wa * ray;
                float dvy = vby + wb * rbx - vay - wa * rax;
                f[po + RELVEL] = dvx * nx + dvy * ny;
            }
            f[fo + BLOCK] = 0f;
            if (c.pointCount == 2) {
                prepareBlock(fo, mA, iA, mB, iB, nx, ny, maxCondition);
            }
        }
        int o = worker * PAD;
        workerLoad[o] = Math.max(workerLoad[o], load);
    }

    /**
     * The heaviest load among the prepared contacts between dynamic bodies: the largest acceleration
     * along its normal that the weight of one body (gravity and applied forces) pressing on the other
     * gives the pair. Over the contact frequency squared, it is how deep the contact sinks under that
     * weight.
     */
    float heaviestLoad() {
        float load = 0f;
        for (int w = 0; w < workerLoad.length; w += PAD) {
            load = Math.max(load, workerLoad[w]);
        }
        return load;
    }

    /** Sets the prepared contacts' softness again, when the solver changed the substep after the prepare. */
    void soften(SolverBodies bodies, Softness soft, Softness staticSoft) {
        float[] st = bodies.state;
        for (int k = 0; k < count; k++) {
            int io = k * CI;
            soften(k * CS, st[n[io + BODY_A] * STRIDE + IM] == 0f || st[n[io + BODY_B] * STRIDE + IM] == 0f, soft, staticSoft);
        }
    }

    /** A contact's softness: against a body of infinite mass (static, frozen or kinematic) the stiffer setting. */
    private void soften(int fo, boolean rigidSide, Softness soft, Softness staticSoft) {
        Softness sf = rigidSide ? staticSoft : soft;
        f[fo + BIAS_RATE] = sf.biasRate;
        f[fo + MASS_SCALE] = sf.massScale;
        f[fo + IMPULSE_SCALE] = sf.impulseScale;
    }

    /**
     * A component of how far the common impulse point moved: half the pair's relative displacement
     * since the tick began, within ±max (0 where the contact has no common point, max 0).
     */
    static float commonPointShift(float relativeDisplacement, float max) {
        if (max == 0f) {
            return 0f;
        }
        float shift = 0.5f * relativeDisplacement;
        return shift > max ? max : (shift < -max ? -max : shift);
    }

    /** The radius of a shape's part if it is a circle, else 0. */
    private static float circleRadius(Shape whole, int part) {
        Shape shape = ContactManager.part(whole, part);
        return shape.getType() == Shape.TYPE_CIRCLE ? ((Circle) shape).getRadius() : 0f;
    }

    /**
     * Gives each contact to solve a slot, colour by colour. The contacts of one colour share no
     * moving body (bodies of zero inverse mass are never written, so they do not count), so they can
     * be solved in any order, or at once, with the same result. Colours are solved in order, so they
     * are chosen to keep the order that makes Gauss–Seidel carry support up a pile in one pass: a
     * contact takes the lowest free colour at or above its level, the number of contacts between it
     * and a body that does not move (a contact on the ground is level 0, the next one up level 1).
     * Greedy colouring from 0 instead solves a column of boxes red–black: ten boxes dropped together
     * at 20 ticks/s then end tilted by 0.28 rad; by level they land flat and rebound at 35 px/s (56
     * with the contacts in the narrowphase's order). A contact that finds no colour goes to the
     * overflow group after the last one. Within a colour the slots keep the contacts' order, so the
     * layout is deterministic, and a tick whose contact graph is the last one's keeps its colouring
     * ({@link ContactGraphKey}).
     */
    private void colour(Contact[] all, boolean[] noPoints, int contactCount, SolverBodies bodies) {
        graph.read(all, noPoints, contactCount);
        // Threads that share the passes solve small islands whole (SolveIslands); the same results.
        boolean threads = pool != null && !pool.isAlone();
        if (keepColouring && graph.matches(contactCount, bodies) && threads == colouredForThreads) {
            return;
        }
        colourings++;
        colouredForThreads = threads;
        islands.clear();
        boolean byIsland = threads && islandsSkipped == 0;
        if (islandsSkipped > 0) {
            islandsSkipped--;
        }
        graph.begin(contactCount, bodies.count);
        float[] st = bodies.state;
        int bodyCount = bodies.count;
        if (usedColours.length < bodyCount * WORDS) {
            int size = Math.max(bodyCount, 2 * usedColours.length / WORDS);
            usedColours = new long[size * WORDS];
            level = new int[size];
            adjacencyStart = new int[size + 1];
            queue = new int[size];
        }
        long[] used = usedColours;
        for (int i = 0; i < bodyCount * WORDS; i++) {
            used[i] = 0L;
        }
        levels(contactCount, bodies);
        if (byIsland) {
            islands.begin(bodyCount, contactCount);
        }
        int[] depth = level;
        int[] sizes = colourStart;
        for (int c = 0; c <= COLOURS + 1; c++) {
            sizes[c] = 0;
        }
        int[] colourOf = slotOf;
        for (int ci = 0; ci < contactCount; ci++) {
            colourOf[ci] = -1;
            int ia = graph.first(ci);
            if (ia < 0) {
                continue;
            }
            int second = graph.second(ci);
            int ib = second >= 0 ? second : 0;
            // Zero inverse mass on both sides (static, frozen or kinematic bodies): nothing to solve.
            if (st[ia * STRIDE + IM] == 0f && st[ib * STRIDE + IM] == 0f) {
                continue;
            }
            boolean movesA = moves(st, ia);
            boolean movesB = moves(st, ib);
            // The first free colour from the level up, else the lowest free one, else the overflow.
            // Half the contacts, by a hash of the pair, start one colour higher: a box's two supports
            // are then solved left first under some boxes and right first under others. Always the
            // same side first shears a tall pyramid (its apex drifted 5.7 px in 10 s at 100 rows).
            int from = Math.min(Math.min(depth[ia], depth[ib]), COLOURS - 1);
            int skew = ((ia * 0x9E3779B1) ^ (ib * 0x85EBCA6B)) >>> 31;
            int start = Math.min(from + skew, COLOURS - 1);
            int colour = freeColour(used, movesA ? ia : -1, movesB ? ib : -1, start);
            if (colour >= COLOURS && start > 0) {
                colour = freeColour(used, movesA ? ia : -1, movesB ? ib : -1, 0);
            }
            if (colour < COLOURS) {
                long bit = 1L << (colour & 63);
                int w = colour >> 6;
                if (movesA) {
                    used[ia * WORDS + w] |= bit;
                }
                if (movesB) {
                    used[ib * WORDS + w] |= bit;
                }
            } else {
                colour = COLOURS;
            }
            colourOf[ci] = colour;
            sizes[colour + 1]++;
            if (byIsland) {
                islands.contact(ci, movesA ? ia : ib, movesA && movesB ? ib : -1);
            }
        }
        if (byIsland) {
            int slots = islands.layout(colourOf, contactCount, colourStart, COLOURS);
            if (islands.split(pool.getThreadCount(), minPart) == 0) {
                // Too few small islands to share: look again only some colourings later (the
                // islands cost a tumbling pile, coloured every tick, 4% of its tick on two threads).
                islandsSkipped = ISLAND_SKIPS;
            }
            if (slots >= 0) {
                count = slots;
                return;
            }
        }
        // Sizes to starts: colour c holds slots colourStart[c] to colourStart[c + 1] − 1.
        for (int c = 1; c <= COLOURS + 1; c++) {
            sizes[c] += sizes[c - 1];
        }
        int[] next = colourFill;
        System.arraycopy(sizes, 0, next, 0, COLOURS + 1);
        for (int ci = 0; ci < contactCount; ci++) {
            int colour = colourOf[ci];
            slotOf[ci] = colour < 0 ? -1 : next[colour]++;
        }
        count = sizes[COLOURS + 1];
    }

    /** The lowest colour from {@code from} up that neither body (−1: none) has taken, or COLOURS. */
    private static int freeColour(long[] used, int a, int b, int from) {
        for (int w = from >> 6; w < WORDS; w++) {
            long free = ~((a >= 0 ? used[a * WORDS + w] : 0L) | (b >= 0 ? used[b * WORDS + w] : 0L));
            if (w == from >> 6) {
                free &= -1L << (from & 63);
            }
            if (free != 0L) {
                return (w << 6) + Long.numberOfTrailingZeros(free);
            }
        }
        return COLOURS;
    }

    private static boolean moves(float[] st, int slot) {
        return st[slot * STRIDE + IM] != 0f || st[slot * STRIDE + II] != 0f;
    }

    /**
     * Each body's level: 0 for a body that does not move, else the fewest touching contacts between
     * it and one that does not (a breadth-first search over the contact graph); bodies that touch
     * nothing still get 0, so that floating clusters start at colour 0.
     */
    private void levels(int contactCount, SolverBodies bodies) {
        float[] st = bodies.state;
        int bodyCount = bodies.count;
        int[] depth = level;
        int[] startOf = adjacencyStart;
        for (int i = 0; i <= bodyCount; i++) {
            startOf[i] = 0;
        }
        int edges = 0;
        for (int ci = 0; ci < contactCount; ci++) {
            int ia = graph.first(ci);
            int ib = graph.second(ci);
            if (ia < 0 || ib < 0) {
                continue;
            }
            startOf[ia + 1]++;
            startOf[ib + 1]++;
            edges += 2;
        }
        for (int i = 1; i <= bodyCount; i++) {
            startOf[i] += startOf[i - 1];
        }
        if (adjacency.length < edges) {
            adjacency = new int[Math.max(edges, 2 * adjacency.length)];
        }
        int[] fill = queue;
        System.arraycopy(startOf, 0, fill, 0, bodyCount);
        for (int ci = 0; ci < contactCount; ci++) {
            int ia = graph.first(ci);
            int ib = graph.second(ci);
            if (ia < 0 || ib < 0) {
                continue;
            }
            adjacency[fill[ia]++] = ib;
            adjacency[fill[ib]++] = ia;
        }
        // Sources: the bodies that do not move, level 0; the rest unreached until found.
        int[] q = queue;
        int tail = 0;
        for (int i = 0; i < bodyCount; i++) {
            graph.body(i, ContactGraphKey.kind(st, i));
            if (i == 0 || !moves(st, i)) {
                depth[i] = 0;
                q[tail++] = i;
            } else {
                depth[i] = Integer.MAX_VALUE;
            }
        }
        // Landscape contacts (no body B) touch the static slot: their body is one step from it.
        for (int ci = 0; ci < contactCount; ci++) {
            int ia = graph.first(ci);
            if (ia >= 0 && graph.second(ci) < 0 && depth[ia] == Integer.MAX_VALUE) {
                depth[ia] = 1;
                q[tail++] = ia;
            }
        }
        for (int head = 0; head < tail; head++) {
            int i = q[head];
            int next = depth[i] + 1;
            for (int e = startOf[i]; e < startOf[i + 1]; e++) {
                int j = adjacency[e];
                if (depth[j] == Integer.MAX_VALUE) {
                    depth[j] = next;
                    q[tail++] = j;
                }
            }
        }
        for (int i = 0; i < bodyCount; i++) {
            if (depth[i] == Integer.MAX_VALUE) {
                depth[i] = 0;
            }
        }
    }

    /**
     * Prepares the joint solve of both normal constraints of a face contact. Solving the two points
     * one after the other favours the first: a tower of boxes then creeps sideways and topples.
     * Solved together the result is exact and symmetric.
     */
    private void prepareBlock(int fo, float mA, float iA, float mB, float iB, float nx, float ny, float maxCondition) {
        int p1 = fo + P0;
        int p2 = p1 + PS;
        float rn1a = f[p1 + RAX] * ny - f[p1 + RAY] * nx;
        float rn1b = f[p1 + RBX] * ny - f[p1 + RBY] * nx;
        float rn2a = f[p2 + RAX] * ny - f[p2 + RAY] * nx;
        float rn2b = f[p2 + RBX] * ny - f[p2 + RBY] * nx;
        float k11 = mA + mB + iA * rn1a * rn1a + iB * rn1b * rn1b;
        float k22 = mA + mB + iA * rn2a * rn2a + iB * rn2b * rn2b;
        float k12 = mA + mB + iA * rn1a * rn2a + iB * rn1b * rn2b;
        float det = k11 * k22 - k12 * k12;
        // Nearly coincident points make the matrix ill-conditioned: solve those point by point.
        if (k11 * k11 < maxCondition * det) {
            float inv = 1f / det;
            f[fo + BLOCK] = 1f;
            f[fo + K11] = k22 * inv;
            f[fo + K12] = -k12 * inv;
            f[fo + K22] = k11 * inv;
        }
    }

    /** Scales the stored impulses, when the substep length changes (dynamic iterations). */
    void scaleImpulses(float factor) {
        for (int k = 0; k < count; k++) {
            int fo = k * CS;
            int pc = n[k * CI + POINTS];
            for (int p = 0; p < pc; p++) {
                int po = fo + P0 + p * PS;
                f[po + NIMP] *= factor;
                f[po + TIMP] *= factor;
            }
        }
    }

    /** Re-applies the accumulated impulses, so a resting stack starts each substep nearly solved. */
    void warmStart(SolverBodies bodies, boolean record) {
        if (record) {
            recordWarmStart();
        }
        passBodies = bodies;
        forColours(warmTask);
    }

    private void warmRange(int from, int to) {
        float[] st = passBodies.state;
        float[] f = this.f;
        int[] n = this.n;
        for (int k = from; k < to; k++) {
            int fo = k * CS;
            int io = k * CI;
            int oa = n[io + BODY_A] * STRIDE;
            int ob = n[io + BODY_B] * STRIDE;
            float nx = f[fo + NX];
            float ny = f[fo + NY];
            float mA = st[oa + IM];
            float iA = st[oa + II];
            float mB = st[ob + IM];
            float iB = st[ob + II];
            float vax = st[oa + VX];
            float vay = st[oa + VY];
            float wa = st[oa + W];
            float vbx = st[ob + VX];
            float vby = st[ob + VY];
            float wb = st[ob + W];
            int pc = n[io + POINTS];
            float sx = commonPointShift(st[ob + DPX] - st[oa + DPX], f[fo + SHIFT]);
            float sy = commonPointShift(st[ob + DPY] - st[oa + DPY], f[fo + SHIFT]);
            for (int p = 0; p < pc; p++) {
                int po = fo + P0 + p * PS;
                float ni = f[po + NIMP];
                float ti = f[po + TIMP];
                float rax = f[po + RAX] + sx;
                float ray = f[po + RAY] + sy;
                float rbx = f[po + RBX] - sx;
                float rby = f[po + RBY] - sy;
                if (ni == 0f && f[po + MAXIMP] == 0f) {
                    // Not touched yet this tick: remember the approach speed just before impact,
                    // which gravity has raised since the tick began, for the hit events.
                    f[po + RELVEL] = (vbx - wb * rby - vax + wa * ray) * nx + (vby + wb * rbx - vay - wa * rax) * ny;
                    continue;
                }
                float px = ni * nx - ti * ny;
                float py = ni * ny + ti * nx;
                vax -= mA * px;
                vay -= mA * py;
                wa -= iA * (rax * py - ray * px);
                vbx += mB * px;
                vby += mB * py;
                wb += iB * (rbx * py - rby * px);
            }
            if (oa != 0) {
                st[oa + VX] = vax;
                st[oa + VY] = vay;
                st[oa + W] = wa;
            }
            if (ob != 0) {
                st[ob + VX] = vbx;
                st[ob + VY] = vby;
                st[ob + W] = wb;
            }
        }
    }

    /** The substep's soft, position-correcting pass over all contacts. */
    void solve(SolverBodies bodies, SubstepContext ctx) {
        pass(bodies, ctx, true, false);
    }

    /**
     * The substep's first rigid relax pass (no position bias), marking the bodies it changes by more
     * than the hot tolerance for {@link #relaxHot}. With a horizon &ge; 0 (dynamic iterations; the
     * warm start must have been recorded) it also measures {@link #lastChange}.
     */
    void relax(SolverBodies bodies, SubstepContext ctx) {
        pass(bodies, ctx, false, false);
    }

    /**
     * Relax passes after the substep's first one, each over the contacts of the bodies the previous
     * pass changed by more than the hot tolerance, until none is or the most passes are done.
     * Gauss–Seidel passes velocity across a mass ratio of r only at about 1/r per pass, so after an
     * impact a heavy body on a light one keeps the soft pass's push (it bounces although elasticity
     * is 0); resting contacts change by less than gravity adds per substep and cost nothing here.
     *
     * @return the passes made
     */
    int relaxHot(SolverBodies bodies, SubstepContext ctx) {
        int made = 0;
        while (made < ctx.maxHotPasses && anyHot) {
            pass(bodies, ctx, false, true);
            made++;
        }
        return made;
    }

    private void pass(SolverBodies bodies, SubstepContext ctx, boolean useBias, boolean hotOnly) {
        passContext = ctx;
        passBodies = bodies;
        passUseBias = useBias;
        passHotOnly = hotOnly;
        passPrevious = pass;
        passCurrent = pass;
        if (!useBias) {
            if (hot.length < bodies.count) {
                hot = new int[Math.max(bodies.count, 2 * hot.length)];
            }
            if (hotOnly) {
                hotContacts.select(n, count, bodies.count);
            }
            hotContacts.clearLists(workerCount(), bodies.count);
            passCurrent = ++pass;
        }
        if (hotOnly) {
            hotPass();
        } else {
            forColours(passTask);
        }
        boolean marked = false;
        float maxChange = 0f;
        for (int w = 0; w < workerCount(); w++) {
            marked |= workerHot[w * PAD] != 0;
            maxChange = Math.max(maxChange, workerChange[w * PAD]);
        }
        if (!useBias) {
            anyHot = marked;
        }
        // Only the substep's first relax pass measures the change (hot passes follow it).
        if (!useBias && !hotOnly && ctx.horizon >= 0f) {
            lastChange = maxChange;
        }
    }

    /** The pass over slots [from, to), by one thread; its findings go to the worker's slots. */
    private void passRange(int worker, int from, int to) {
        SubstepContext ctx = passContext;
        boolean useBias = passUseBias;
        boolean hotOnly = passHotOnly;
        float invH = ctx.invH;
        float maxPush = ctx.maxPush;
        float slop = ctx.slop;
        float hotTolerance = useBias ? Float.POSITIVE_INFINITY : ctx.hotTolerance;
        float horizon = ctx.horizon;
        float gravityX = ctx.gravityX;
        float gravityY = ctx.gravityY;
        boolean trackChange = !useBias && !hotOnly && horizon >= 0f;
        float[] st = passBodies.state;
        float maxChange = 0f;
        boolean marked = false;
        int[] hotStamp = hot;
        int previous = passPrevious;
        int current = passCurrent;
        float[] f = this.f;
        int[] n = this.n;
        for (int k = from; k < to; k++) {
            int fo = k * CS;
            int io = k * CI;
            int ia = n[io + BODY_A];
            int ib = n[io + BODY_B];
            if (hotOnly && hotStamp[ia] != previous && hotStamp[ib] != previous) {
                continue;
            }
            int oa = ia * STRIDE;
            int ob = ib * STRIDE;
            float nx = f[fo + NX];
            float ny = f[fo + NY];
            float mA = st[oa + IM];
            float iA = st[oa + II];
            float mB = st[ob + IM];
            float iB = st[ob + II];
            float vax = st[oa + VX];
            float vay = st[oa + VY];
            float wa = st[oa + W];
            float vbx = st[ob + VX];
            float vby = st[ob + VY];
            float wb = st[ob + W];
            // Motion of the two bodies since the tick started.
            float dpx = st[ob + DPX] - st[oa + DPX];
            float dpy = st[ob + DPY] - st[oa + DPY];
            // Impulses between two dynamic bodies act at one point, midway between where each body
            // carried the contact point since the tick began, so that they change no angular
            // momentum; with the tick's arms they turned the pair by (dpB - dpA) x P each.
            float sx = commonPointShift(dpx, f[fo + SHIFT]);
            float sy = commonPointShift(dpy, f[fo + SHIFT]);
            float qac = st[oa + DQC];
            float qas = st[oa + DQS];
            float qbc = st[ob + DQC];
            float qbs = st[ob + DQS];
            float biasRate = f[fo + BIAS_RATE];
            float softMass = f[fo + MASS_SCALE];
            float softImpulse = f[fo + IMPULSE_SCALE];
            int pc = n[io + POINTS];
            float friction = f[fo + FRICTION];

            boolean solved = false;
            if (f[fo + BLOCK] != 0f) {
                int p1 = fo + P0;
                int p2 = p1 + PS;
                float r1ax = f[p1 + RAX];
                float r1ay = f[p1 + RAY];
                float r1bx = f[p1 + RBX];
                float r1by = f[p1 + RBY];
                float r2ax = f[p2 + RAX];
                float r2ay = f[p2 + RAY];
                float r2bx = f[p2 + RBX];
                float r2by = f[p2 + RBY];
                float s1 = (dpx + qbc * r1bx - qbs * r1by - qac * r1ax + qas * r1ay) * nx
                    + (dpy + qbs * r1bx + qbc * r1by - qas * r1ax - qac * r1ay) * ny + f[p1 + BASE_SEP];
                float s2 = (dpx + qbc * r2bx - qbs * r2by - qac * r2ax + qas * r2ay) * nx
                    + (dpy + qbs * r2bx + qbc * r2by - qas * r2ax - qac * r2ay) * ny + f[p2 + BASE_SEP];
                r1ax += sx;
                r1ay += sy;
                r1bx -= sx;
                r1by -= sy;
                r2ax += sx;
                r2ay += sy;
                r2bx -= sx;
                r2by -= sy;
                // Both points touching: solve them together. A speculative point goes point by point.
                if (s1 <= 0f && s2 <= 0f) {
                    float ms = useBias ? softMass : 1f;
                    float is = useBias ? softImpulse : 0f;
                    float b1 = 0f;
                    float b2 = 0f;
                    if (useBias) {
                        b1 = pushBias(s1 + slop, biasRate, maxPush);
                        b2 = pushBias(s2 + slop, biasRate, maxPush);
                    }
                    float e1 = (vbx - wb * r1by - vax + wa * r1ay) * nx + (vby + wb * r1bx - vay - wa * r1ax) * ny + b1;
                    float e2 = (vbx - wb * r2by - vax + wa * r2ay) * nx + (vby + wb * r2bx - vay - wa * r2ax) * ny + b2;
                    float a1 = f[p1 + NIMP];
                    float a2 = f[p2 + NIMP];
                    float x1 = a1 - ms * (f[fo + K11] * e1 + f[fo + K12] * e2) - is * a1;
                    float x2 = a2 - ms * (f[fo + K12] * e1 + f[fo + K22] * e2) - is * a2;
                    // Both impulses pushing: accept. Otherwise one point separates; the sequential
                    // solve below handles that case.
                    if (x1 >= 0f && x2 >= 0f) {
                        solved = true;
                        float d1 = x1 - a1;
                        float d2 = x2 - a2;
                        f[p1 + NIMP] = x1;
                        f[p2 + NIMP] = x2;
                        if (d1 > f[p1 + MAXIMP]) {
                            f[p1 + MAXIMP] = d1;
                        }
                        if (d2 > f[p2 + MAXIMP]) {
                            f[p2 + MAXIMP] = d2;
                        }
                        float px = (d1 + d2) * nx;
                        float py = (d1 + d2) * ny;
                        if (!useBias) {
                            marked |= markHot(worker, mA == 0f ? 0 : ia, mB == 0f ? 0 : ib, Math.max(Math.abs(d1) * f[p1 + KN], Math.abs(d2) * f[p2 + KN]),
                                hotTolerance, current);
                        }
                        vax -= mA * px;
                        vay -= mA * py;
                        wa -= iA * ((r1ax * ny - r1ay * nx) * d1 + (r2ax * ny - r2ay * nx) * d2);
                        vbx += mB * px;
                        vby += mB * py;
                        wb += iB * ((r1bx * ny - r1by * nx) * d1 + (r2bx * ny - r2by * nx) * d2);
                    }
                }
            }
            for (int p = 0; p < pc && !solved; p++) {
                int po = fo + P0 + p * PS;
                float rax = f[po + RAX];
                float ray = f[po + RAY];
                float rbx = f[po + RBX];
                float rby = f[po + RBY];
                // Current separation from the anchors carried along by each body's rotation.
                float prax = qac * rax - qas * ray;
                float pray = qas * rax + qac * ray;
                float prbx = qbc * rbx - qbs * rby;
                float prby = qbs * rbx + qbc * rby;
                float sep = (dpx + prbx - prax) * nx + (dpy + prby - pray) * ny + (f[fo + CIRCLE_A] * qac - f[fo + CIRCLE_B] * qbc)
                    + f[po + BASE_SEP];
                rax += sx;
                ray += sy;
                rbx -= sx;
                rby -= sy;
                float bias = 0f;
                float massScale = 1f;
                float impulseScale = 0f;
                if (sep > 0f) {
                    // Speculative: allow closing exactly the gap this substep.
                    bias = sep * invH;
                } else if (useBias) {
                    bias = pushBias(sep + slop, biasRate, maxPush);
                    massScale = softMass;
                    impulseScale = softImpulse;
                }
                float dvx = vbx - wb * rby - vax + wa * ray;
                float dvy = vby + wb * rbx - vay - wa * rax;
                float vn = dvx * nx + dvy * ny;
                float old = f[po + NIMP];
                float nm = f[po + NMASS];
                float acc = old - nm * massScale * (vn + bias) - impulseScale * old;
                if (acc < 0f) {
                    acc = 0f;
                }
                f[po + NIMP] = acc;
                float d = acc - old;
                if (d > f[po + MAXIMP]) {
                    f[po + MAXIMP] = d;
                }
                if (!useBias) {
                    marked |= markHot(worker, mA == 0f ? 0 : ia, mB == 0f ? 0 : ib, Math.abs(d) * f[po + KN], hotTolerance, current);
                }
                float px = d * nx;
                float py = d * ny;
                vax -= mA * px;
                vay -= mA * py;
                wa -= iA * (rax * py - ray * px);
                vbx += mB * px;
                vby += mB * py;
                wb += iB * (rbx * py - rby * px);
            }

            // Friction, bounded by the normal impulse of this pass (Coulomb cone).
            for (int p = 0; p < pc; p++) {
                int po = fo + P0 + p * PS;
                float maxF = friction * f[po + NIMP];
                // No normal impulse and no friction impulse to take back (a speculative point, or one
                // separating): the clamp would leave a zero (of either sign) and change no velocity but
                // the sign of a zero one. In 58% of the tumbler's contact visits no point has an impulse;
                // it runs 7-9% faster.
                if (maxF == 0f && f[po + TIMP] == 0f) {
                    continue;
                }
                float rax = f[po + RAX] + sx;
                float ray = f[po + RAY] + sy;
                float rbx = f[po + RBX] - sx;
                float rby = f[po + RBY] - sy;
                float dvx = vbx - wb * rby - vax + wa * ray;
                float dvy = vby + wb * rbx - vay - wa * rax;
                float vt = -dvx * ny + dvy * nx;
                float old = f[po + TIMP];
                float acc = old - f[po + TMASS] * vt;
                acc = acc < -maxF ? -maxF : (acc > maxF ? maxF : acc);
                f[po + TIMP] = acc;
                float d = acc - old;
                float px = -d * ny;
                float py = d * nx;
                vax -= mA * px;
                vay -= mA * py;
                wa -= iA * (rax * py - ray * px);
                vbx += mB * px;
                vby += mB * py;
                wb += iB * (rbx * py - rby * px);
            }

            if (trackChange) {
                for (int p = 0; p < pc; p++) {
                    int po = fo + P0 + p * PS;
                    float rax = f[po + RAX];
                    float ray = f[po + RAY];
                    float rbx = f[po + RBX];
                    float rby = f[po + RBY];
                    float dn = f[po + NIMP] - warm[4 * k + 2 * p];
                    float dt = f[po + TIMP] - warm[4 * k + 2 * p + 1];
                    float tm = f[po + TMASS];
                    float dv = Math.max(Math.abs(dn) * f[po + KN], tm > 0f ? Math.abs(dt) / tm : 0f);
                    float sep = (dpx + qbc * rbx - qbs * rby - qac * rax + qas * ray) * nx
                        + (dpy + qbs * rbx + qbc * rby - qas * rax - qac * ray) * ny
                        + (f[fo + CIRCLE_A] * qac - f[fo + CIRCLE_B] * qbc) + f[po + BASE_SEP];
                    if (sep > 0f) {
                        // A gap that could close before the tick ends needs the solve: warm starts alone
                        // would let the bodies pass into each other. Gravity closes only gaps to static
                        // and kinematic bodies (zero inverse mass), at its component along the normal.
                        float vn = (vbx - wb * rby - vax + wa * ray) * nx + (vby + wb * rbx - vay - wa * rax) * ny;
                        float an = mA == 0f ? gravityX * nx + gravityY * ny : (mB == 0f ? -gravityX * nx - gravityY * ny : 0f);
                        float reach = ((vn < 0f ? vn : 0f) + (an < 0f ? an : 0f) * horizon) * horizon;
                        if (sep + reach <= 0f) {
                            dv = Float.POSITIVE_INFINITY;
                        }
                    }
                    if (dv > maxChange) {
                        maxChange = dv;
                    }
                }
            }
            if (oa != 0) {
                st[oa + VX] = vax;
                st[oa + VY] = vay;
                st[oa + W] = wa;
            }
            if (ob != 0) {
                st[ob + VX] = vbx;
                st[ob + VY] = vby;
                st[ob + W] = wb;
            }
        }
        // A worker runs several ranges per pass (one per colour): its findings add up.
        int o = worker * PAD;
        workerChange[o] = Math.max(workerChange[o], maxChange);
        if (marked) {
            workerHot[o] = 1;
        }
    }

    /**
     * Runs a task over every slot: with a worker pool, the large islands' slots colour by colour, each
     * colour large enough split among the threads (its contacts share no moving body, so the split
     * changes nothing), their overflow group on this thread, then the small islands' runs, one a thread
     * ({@link SolveIslands}). Without one, all slots in order, which gives the same results.
     */
    private void forColours(WorkerPool.RangeTask task) {
        WorkerPool p = pool;
        for (int w = 0; w < workerCount(); w++) {
            workerChange[w * PAD] = 0f;
            workerHot[w * PAD] = 0;
        }
        if (p == null) {
            task.run(0, 0, count);
            return;
        }
        for (int c = 0; c < COLOURS; c++) {
            int from = colourStart[c];
            int to = colourStart[c + 1];
            if (from != to) {
                p.run(task, from, to, minPart);
            }
        }
        int small = colourStart[COLOURS + 1];
        task.run(0, colourStart[COLOURS], small);
        // The small islands: a run of whole islands for each thread, one wait for all of them.
        int runs = islands.parts();
        if (runs > 0) {
            runTask = task;
            p.run(islandRuns, 0, runs, 1);
            runTask = null;
        } else if (small < count) {
            task.run(0, small, count);
        }
    }

    /** A hot pass over the selected slots in slot order, by the calling thread (a few contacts each). */
    private void hotPass() {
        for (int w = 0; w < workerCount(); w++) {
            workerChange[w * PAD] = 0f;
            workerHot[w * PAD] = 0;
        }
        int k = hotContacts.next(0, count);
        while (k < count) {
            int end = hotContacts.runEnd(k, count);
            passRange(0, k, end);
            k = hotContacts.next(end, count);
        }
    }

    /** The runs of small islands the threads share in a pass (0: laid out by colour alone), for tests. */
    int islandRuns() {
        return islands.parts();
    }

    private int workerCount() {
        return pool == null ? 1 : pool.getThreadCount();
    }

    /** Keeps each point's warm-start impulses, from which {@link #lastChange} is measured. */
    private void recordWarmStart() {
        if (warm.length < 4 * count) {
            warm = new float[4 * contacts.length];
        }
        for (int k = 0; k < count; k++) {
            int fo = k * CS;
            int pc = n[k * CI + POINTS];
            for (int p = 0; p < pc; p++) {
                int po = fo + P0 + p * PS;
                warm[4 * k + 2 * p] = f[po + NIMP];
                warm[4 * k + 2 * p + 1] = f[po + TIMP];
            }
        }
    }

    /**
     * Marks both bodies for the next hot pass when an impulse changed their relative speed by more
     * than tolerance; true when it did.
     */
    private boolean markHot(int worker, int ia, int ib, float change, float tolerance, int current) {
        if (change > tolerance) {
            // Slot 0 is every static body: marking it would make all static contacts hot. Callers pass 0
            // for a kinematic body too, whose velocity no impulse changes.
            if (ia != 0 && hot[ia] != current) {
                hot[ia] = current;
                hotContacts.list(worker, ia);
            }
            if (ib != 0 && hot[ib] != current) {
                hot[ib] = current;
                hotContacts.list(worker, ib);
            }
            return true;
        }
        return false;
    }

    /** Push-out velocity for a penetration beyond the slop (negative), capped at maxPush. */
    private static float pushBias(float depthBeyondSlop, float biasRate, float maxPush) {
        if (depthBeyondSlop >= 0f) {
            return 0f;
        }
        float bias = biasRate * depthBeyondSlop;
        return bias < -maxPush ? -maxPush : bias;
    }

    /** The substep's elastic impacts, before its warm start ({@link ElasticImpacts}). */
    void impacts(SolverBodies bodies, float h, float threshold, float slop, StepData step) {
        impacts.run(f, n, contacts, contactOf, bodies, h, threshold, slop, step);
    }

    /**
     * Copies the impulses back to the persistent contacts for warm starting and queries, and
     * reports as hits the contacts whose fastest-approaching point that took an impulse came in
     * faster than the threshold (infinite: no hits, no cost).
     */
    void storeImpulses(StepData step, float hitSpeed) {
        if (hitSpeed < Float.POSITIVE_INFINITY) {
            // In the contacts' order, not the slots' (which depends on how threads share the solve).
            for (int ci = 0; ci < preparedCount; ci++) {
                int k = slotOf[ci];
                if (k < 0) {
                    continue;
                }
                int fo = k * CS;
                int pc = n[k * CI + POINTS];
                float fastest = hitSpeed;
                int hitPoint = -1;
                for (int p = 0; p < pc; p++) {
                    int po = fo + P0 + p * PS;
                    // The relative velocity along the normal is negative while the bodies approach.
                    if (f[po + MAXIMP] > 0f && -f[po + RELVEL] > fastest) {
                        fastest = -f[po + RELVEL];
                        hitPoint = p;
                    }
                }
                if (hitPoint >= 0) {
                    step.contactHit(contacts[k], hitPoint, fastest);
                }
            }
        }
        if (pool != null) {
            pool.run(storeTask, 0, count, minPart);
        } else {
            storeRange(0, count);
        }
    }

    /** Copies the impulses of slots [from, to) to their contacts (each slot its own contact). */
    private void storeRange(int from, int to) {
        for (int k = from; k < to; k++) {
            Contact c = contacts[k];
            int fo = k * CS;
            int pc = n[k * CI + POINTS];
            for (int p = 0; p < pc; p++) {
                int po = fo + P0 + p * PS;
                c.setImpulses(p, f[po + NIMP], f[po + TIMP], f[po + MAXIMP]);
            }
            contacts[k] = null;
        }
    }

    private void ensure(int capacity) {
        if (slotOf.length < capacity) {
            slotOf = new int[Math.max(capacity, slotOf.length * 2)];
            graph.forget();
        }
        if (contacts.length < capacity) {
            int c = Math.max(capacity, contacts.length * 2);
            contacts = new Contact[c];
            contactOf = new int[c];
            f = new float[c * CS];
            n = new int[c * CI];
        }
    }
}
