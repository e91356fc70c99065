package org.emini.dynamics;

import org.emini.collision.BroadPhase;
import org.emini.internal.WorkerPool;
import org.emini.math.EMath;

/**
 * The solve of one tick: the soft step of Box2D v3 (Catto's "solver2d" study) on flat copies of the
 * simulated bodies. The tick is split into substeps, one per iteration (more where the sink limit
 * asks: {@link SolverSettings#getSinkLimit()}); each integrates velocities,
 * bounces the elastic impacts that close within it, warm-starts the constraints and contacts, makes
 * one soft (position-correcting) pass, integrates positions and makes rigid relax passes. Then the
 * constraints' finish, the continuous pass that keeps fast bodies from passing through static ones,
 * and the write-back with damping.
 *
 * <p>In dynamic-iteration mode the solve stops once a substep's impulses equal those it started
 * from (within the convergence tolerance, as velocity) and no speculative gap can close in the rest
 * of the tick; the remaining substeps only integrate and re-apply those impulses.
 */
final class Solver {
    final SolverBodies bodies = new SolverBodies();
    final SolverStep step;
    private final ContactSolver contacts = new ContactSolver();
    private final ContinuousSolver continuous;
    private final Softness soft = new Softness();
    private final Softness staticSoft = new Softness();
    private final SubstepContext context = new SubstepContext();
    // From copying the bodies in to writing them back: what the application sets on a body then
    // must reach the copy.
    private boolean solving;
    private float lastSubstep;
    private int lastIterationCount;

    private final Simulation world;
    /** The fewest bodies worth a thread in the per-body loops (each body takes a few nanoseconds). */
    static final int MIN_BODIES = 256;
    /** Per-part results sit this many ints apart, so that threads do not share a cache line. */
    private static final int PAD = 16;
    private WorkerPool pool;
    private int minBodies = MIN_BODIES;
    // What the per-body tasks below read: the tick's inputs, and what each part found.
    private Body[] copyList;
    private float copyGravityX;
    private float copyGravityY;
    private long copyTick;
    private float substep;
    private float linearKeep;
    private float angularKeep;
    private int[] partFound = new int[PAD];
    private final WorkerPool.RangeTask copyInTask = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            partFound[part * PAD] = bodies.copyIn(copyList, from, to, copyGravityX, copyGravityY, copyTick);
        }
    };
    private final WorkerPool.RangeTask integrateTask = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            bodies.integratePositions(substep, from, to);
        }
    };
    private final WorkerPool.RangeTask markTask = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            continuous.mark(bodies, from, to);
        }
    };
    private final WorkerPool.RangeTask writeBackTask = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            partFound[part * PAD] = bodies.writeBack(linearKeep, angularKeep, from, to);
        }
    };

    Solver(Simulation world) {
        this.world = world;
        step = new SolverStep(bodies, world);
        continuous = new ContinuousSolver(world);
    }

    /** Shares the contact passes and the position integration with a pool's threads, or not (null). */
    void setPool(WorkerPool pool) {
        this.pool = pool;
        contacts.setPool(pool);
        partFound = new int[(pool == null ? 1 : pool.getThreadCount()) * PAD];
    }

    /** The fewest bodies, and contacts of a colour, given to a thread (Simulation.setSplitAlways). */
    void setMinParallelPart(int bodies, int contacts) {
        this.contacts.minPart = contacts;
        minBodies = bodies;
    }

    /**
     * Runs a per-body task over [from, to), shared with the pool's threads when there is one, and
     * returns how many parts it made (their results are in partFound).
     */
    private int forBodies(WorkerPool.RangeTask task, int from, int to) {
        int threads = pool == null ? 1 : pool.getThreadCount();
        for (int w = 0; w < threads; w++) {
            partFound[w * PAD] = 0;
        }
        if (pool == null) {
            task.run(0, from, to);
            return 1;
        }
        pool.run(task, from, to, minBodies);
        return threads;
    }

    /** Copies the simulated bodies into the solver's slots (body i to slot i + 1). */
    private void copyIn(Body[] simulated, int simulatedCount, float gravityX, float gravityY, long tick) {
        bodies.reset(simulatedCount);
        copyList = simulated;
        copyGravityX = gravityX;
        copyGravityY = gravityY;
        copyTick = tick;
        int parts = forBodies(copyInTask, 0, simulatedCount);
        copyList = null;
        int kinematic = 0;
        for (int w = 0; w < parts; w++) {
            kinematic += partFound[w * PAD];
        }
        bodies.kinematicCount = kinematic;
    }

    private void integratePositions(float h) {
        substep = h;
        forBodies(integrateTask, 1, bodies.count);
        bodies.owing = false;
    }

    /** Writes the state back to the bodies; returns the first body that left the finite range, or null. */
    private Body writeBack(Body[] simulated, float linearDamped, float angularDamped) {
        linearKeep = linearDamped;
        angularKeep = angularDamped;
        int end = bodies.count;
        int parts = forBodies(writeBackTask, 1, end);
        int first = end;
        for (int w = 0; w < parts; w++) {
            int found = partFound[w * PAD];
            // 0: none in its part, or no part.
            if (found != 0) {
                first = Math.min(first, found);
            }
        }
        return first < end ? simulated[first - 1] : null;
    }

    /** The contact solver, for tests of its internals. */
    ContactSolver contactSolver() {
        return contacts;
    }

    boolean isSolving() {
        return solving;
    }

    /** Refuses a change of a body's pose, shape or kind while the solver holds a copy of it. */
    void checkNotSolving(String where) {
        if (solving) {
            throw new IllegalStateException(where + ": cannot change a body's pose, shape or kind while the world solves"
                + " a tick (from a Constraint); change it before tick(), or from an ExternalForce or an event listener");
        }
    }

    // While the solver holds a copy of a body (from a Constraint), what the application changes of
    // its velocity and forces reaches the copy; velocities otherwise read from the body are stale.

    void velocitySet(Body b) {
        if (solving && b.solverIndex != 0) {
            bodies.setVelocity(b, b.vx, b.vy, b.w);
        }
    }

    void impulseApplied(Body b, float dvx, float dvy, float dw) {
        if (solving && b.solverIndex != 0) {
            bodies.addVelocity(b, dvx, dvy, dw);
        }
    }

    void forcesChanged(Body b) {
        if (solving && b.solverIndex != 0) {
            bodies.refreshForces(b, world.getGravityX(), world.getGravityY(), world.getTickCount());
        }
    }

    int getLastIterationCount() {
        return lastIterationCount;
    }

    /**
     * Solves the tick.
     *
     * @param world the world, for its settings
     * @param simulated the bodies to move, {@code simulatedCount} of them
     * @param active the contacts the narrowphase updated, {@code activeCount} of them
     * @param noPoints per active contact, whether the narrowphase left it without points
     * @param constraints the constraints, {@code constraintCount} of them, solved in this order
     * @param broadPhase for the continuous pass
     * @return null, or the first body whose state left the range of finite numbers (when the
     *     continuous pass found it, nothing was written back)
     */
    Body solve(Simulation world, Body[] simulated, int simulatedCount, Contact[] active, boolean[] noPoints, int activeCount,
            Constraint[] constraints, int constraintCount, BroadPhase broadPhase) {
        float dt = world.getTimestep();
        int n = world.getConstraintIterations();
        boolean dynamicIterations = world.isConstraintIterationDynamic();
        float gravityX = world.getGravityX();
        float gravityY = world.getGravityY();
        long tick = world.getTickCount();
        SolverSettings settings = world.getSolverSettings();
        float h = dt / n;
        SolverBodies sb = bodies;
        copyIn(simulated, simulatedCount, gravityX, gravityY, tick);
        solving = true;
        setSoftness(settings, h);
        contacts.prepare(active, noPoints, activeCount, sb, soft, staticSoft, settings.getBlockConditionLimit(),
            lastSubstep != 0f ? lastSubstep : h);
        int sinkSubsteps = sinkSubsteps(settings, dt, n, contacts.heaviestLoad());
        if (sinkSubsteps > n) {
            n = sinkSubsteps;
            h = dt / n;
            setSoftness(settings, h);
            contacts.soften(sb, soft, staticSoft);
        }
        step.begin(dt, h, settings);
        // Stored impulses belong to the substep they were computed for.
        if (lastSubstep != 0f && lastSubstep != h) {
            contacts.scaleImpulses(h / lastSubstep);
        }
        Constraint[] cs = constraints;
        int cn = constraintCount;
        for (int c = 0; c < cn; c++) {
            cs[c].prepare(step);
        }
        SubstepContext ctx = context;
        ctx.invH = 1f / h;
        ctx.maxPush = settings.getContactPushMaxVelocity();
        ctx.slop = settings.getLinearSlop();
        ctx.hotTolerance = settings.getImpactTolerance();
        ctx.maxHotPasses = settings.getImpactRelaxPasses();
        ctx.gravityX = gravityX;
        ctx.gravityY = gravityY;
        float tolerance = settings.getConvergenceTolerance();
        int used = 0;
        boolean converged = false;
        float restitutionThreshold = settings.getRestitutionThreshold();
        for (int i = 0; i < n; i++) {
            // Not shared with the threads: about 2 ns a body, less than a hand-off (shared, the
            // tumbler ran 4-7% slower at two threads).
            sb.integrateVelocities(h);
            contacts.impacts(sb, h, restitutionThreshold, ctx.slop, world.stepData);
            for (int c = 0; c < cn; c++) {
                cs[c].warmStart(step);
            }
            contacts.warmStart(sb, dynamicIterations && !converged);
            // Once converged, every later substep repeats the warm start alone: valid only while
            // the impulses of a substep equal those it started from, which is what converged means.
            if (!converged) {
                for (int c = 0; c < cn; c++) {
                    cs[c].solve(step, true);
                }
                contacts.solve(sb, ctx);
            }
            integratePositions(h);
            if (!converged) {
                float change = 0f;
                for (int c = 0; c < cn; c++) {
                    change = Math.max(change, cs[c].solve(step, false));
                }
                ctx.horizon = dynamicIterations ? (n - 1 - i) * h : -1f;
                contacts.relax(sb, ctx);
                int hotPasses = contacts.relaxHot(sb, ctx);
                used++;
                converged = dynamicIterations && hotPasses == 0 && Math.max(change, contacts.lastChange) < tolerance;
            }
        }
        contacts.storeImpulses(world.stepData, world.getHitEventThreshold());
        for (int c = 0; c < cn; c++) {
            cs[c].finish(step);
            if (!(Math.abs(cs[c].getForce()) <= Float.MAX_VALUE)) {
                solving = false;
                throw new IllegalStateException("World.tick: constraint " + c + " (" + cs[c] + ") exerted a force of "
                    + cs[c].getForce() + " in tick " + tick + ", beyond the range of finite numbers; check the forces,"
                    + " velocities, gravity and timestep of its bodies");
            }
        }
        lastSubstep = h;
        lastIterationCount = used;
        continuous.begin(sb.count);
        forBodies(markTask, 1, sb.count);
        Body escaped = continuous.solve(sb, broadPhase, settings.getTimeOfImpactTarget());
        if (escaped != null) {
            // Not written back: the bodies keep their last finite poses.
            solving = false;
            return escaped;
        }
        Body bad = writeBack(simulated, 1f - world.getDampingLateral(), 1f - world.getDampingRotational());
        solving = false;
        return bad;
    }

    /** Resets the solve phase after a failure inside it (a constraint threw). */
    void abort() {
        solving = false;
    }

    /**
     * The fewest substeps, from n up to the sink limit's factor times n, at which the heaviest load
     * sinks its contact no deeper than the limit (see {@link SolverSettings#getSinkLimit()}). A
     * contact of frequency ω sinks by its load's acceleration over ω²; substeps raise ω until the
     * contact frequency setting caps it.
     */
    private int sinkSubsteps(SolverSettings settings, float dt, int n, float load) {
        float limit = settings.getSinkLimit();
        if (!(load > 0f) || limit == Float.POSITIVE_INFINITY) {
            return n;
        }
        // Never beyond the iteration count's own range.
        int most = Math.max(n, Math.min((int) (n * settings.getSinkSubstepFactor()), 1000));
        for (int m = n; m < most; m++) {
            float hertz = contactHertz(settings, dt / m);
            float omega = EMath.TWO_PI * hertz;
            if (load <= limit * omega * omega || hertz == settings.getContactHertz()) {
                return m;
            }
        }
        return most;
    }

    /** The contact frequency over substeps of h: the setting, capped at a fraction of the substep rate. */
    private static float contactHertz(SolverSettings settings, float h) {
        return Math.min(settings.getContactHertz(), settings.getSubstepHertzRatio() / h);
    }

    private void setSoftness(SolverSettings settings, float h) {
        float hertz = contactHertz(settings, h);
        soft.set(hertz, settings.getContactDampingRatio(), h);
        staticSoft.set(2f * hertz, settings.getContactDampingRatio(), h);
    }
}
