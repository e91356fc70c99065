package org.emini.dynamics;

import java.util.Arrays;
import org.emini.collision.BroadPhase;
import org.emini.collision.PairCallback;
import org.emini.collision.QueryCallback;
import org.emini.internal.HeapSort;
import org.emini.internal.WorkerPool;
import org.emini.shape.MultiShape;
import org.emini.shape.Shape;

/**
 * Where contacts are born, updated and forgotten.
 *
 * <p>Every part of a body's shape has its own broadphase proxy (one for a plain shape, one per part
 * of a multi-shape; {@link PartKeys}). A contact is created when the broadphase reports that two
 * parts' fat boxes began to overlap and their bodies may collide, or when a dynamic body's part's fat
 * box comes to overlap a landscape segment's box; it is updated by the narrowphase every tick and
 * destroyed when the boxes separate or the pair's filter changes. So a multi-shape body has one
 * contact per pair of parts that are near (and per part and segment), each with its own feature ids
 * for warm starting. Contact objects are pooled, so steady-state ticking allocates nothing.
 *
 * <p>Each tick only the active contacts, those of the bodies being simulated, are collided and
 * solved; they are kept in contact-array order so the result does not depend on how they were
 * collected.
 */
final class ContactManager implements PairCallback, QueryCallback {
    private final Simulation world;
    private final PartKeys parts;
    // This tick's ManifoldReuse tolerance: the setting, at most half the speculative distance.
    private float reuseTolerance;
    /** The fewest contacts given to a thread: one takes about a tenth of a microsecond to collide. */
    static final int MIN_PART = 64;
    // One narrowphase per thread (index 0: the calling thread's), and the pool, or null.
    private NarrowPhase[] narrow = {new NarrowPhase()};
    private WorkerPool workers;
    /** The fewest contacts given to a thread (MIN_PART; tests lower it to split any range). */
    int minPart = MIN_PART;
    // Per active contact: what its narrowphase found (NarrowPhase.ALIVE, DEAD or FILTER).
    private byte[] outcome = new byte[64];
    // The collide phase's inputs, as the range task reads them.
    private BroadPhase phaseBroadPhase;
    private float phaseSweepTime;
    private float phaseSpeculative;
    private final WorkerPool.RangeTask collideTask = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            collideRange(part, from, to);
        }
    };
    Contact[] contacts = new Contact[64];
    int count;
    private Contact[] pool = new Contact[64];
    private int poolCount;
    /** The contacts collided and solved this tick. */
    Contact[] active = new Contact[64];
    int activeCount;
    // Per active contact: its index in contacts (read without the object; the position itself when
    // all contacts are active, in order), and whether the narrowphase left it without points (the
    // colouring then need not read it either).
    private int[] activeIndex = new int[64];
    private boolean activeIsAll;
    boolean[] noPoints = new boolean[64];
    private final ApartPairs apart = new ApartPairs();
    private long[] keys = new long[64];
    // The segments a body's landscape query found, sorted before their contacts are made.
    private long[] foundSlots = new long[16];
    private int foundCount;
    /** The pairs in contact, so that a reported pair is checked in O(1). */
    private final PairCounts pairs = new PairCounts();
    /** Whether this tick left a pair without contacts: the world was at its contact capacity. */
    boolean capacityReached;
    // Every contact object made, by serial: what a handle names.
    private Contact[] all = new Contact[16];
    private int allCount;

    // The landscape the contacts refer to; its changes advance the epoch, and a body whose epoch
    // is behind looks for its segments again.
    private Landscape landscape;
    private int landscapeModCount;
    private int landscapeEpoch;
    ContactManager(Simulation world, PartKeys keys) {
        this.world = world;
        this.parts = keys;
    }

    /**
     * The built-in rules: one body dynamic (static and kinematic bodies never meet each other), both
     * interacting, no shared layer (the original engine's rule), Box2D's categories, masks and
     * groups, and no {@link Simulation#disableCollision}.
     */
    static boolean shouldCollide(Body a, Body b) {
        return (a.isDynamic() || b.isDynamic()) && !a.sensor && !b.sensor && filterAllows(a, b);
    }

    /** The filter alone: interacting, no shared layer bit, collision not switched off for the pair. */
    static boolean filterAllows(Body a, Body b) {
        return a.isInteracting() && b.isInteracting()
            && (a.getCollisionLayers() & b.getCollisionLayers()) == 0
            && Body.filterAllows(a, b)
            && (a.noCollideCount == 0 || !a.excludes(b));
    }

    /** The application's filter, when set, after the built-in rules allowed the pair. */
    private boolean filterAccepts(Body a, Body b) {
        CollisionFilter filter = world.getCollisionFilter();
        return filter == null || filter.shouldCollide(a, b);
    }

    static int partCount(Shape s) {
        return s.getType() == Shape.TYPE_MULTI ? ((MultiShape) s).getShapeCount() : 1;
    }

    static Shape part(Shape s, int i) {
        return s.getType() == Shape.TYPE_MULTI ? ((MultiShape) s).getShape(i) : s;
    }

    /** Two parts' fat boxes began to overlap, and they have no contact ({@link #isKnownPair}): one, unless they may not collide. */
    @Override
    public void addPair(int keyA, int keyB) {
        Body a = parts.body(keyA);
        Body b = parts.body(keyB);
        // Two parts of one body overlap: nothing to do.
        if (a == b || !shouldCollide(a, b)) {
            return;
        }
        if (!filterAccepts(a, b) || full(1)) {
            return;
        }
        create(a, b, keyA, keyB);
    }

    /** A pair in contact is left out by the broadphase: in a moving crowd most pairs it finds are. */
    @Override
    public boolean isKnownPair(int keyA, int keyB) {
        return pairs.contains(PairCounts.parts(keyA, keyB));
    }

    /** Whether n more contacts would exceed the world's capacity (noted for the tick if so). */
    private boolean full(int n) {
        if (count + n <= world.getSolverSettings().getMaxContacts()) {
            return false;
        }
        capacityReached = true;
        return true;
    }

    /** Reports the broadphase's new pairs, at most the contact capacity of them. */
    void updatePairs(BroadPhase broadPhase) {
        broadPhase.setPairLimit(world.getSolverSettings().getMaxContacts());
        broadPhase.updatePairs(this);
        capacityReached |= broadPhase.isPairLimitReached();
    }

    /** A contact of part keyA of body a and part keyB of body b, or of a's part and a segment when b is null (keyB −1). */
    private Contact create(Body a, Body b, int keyA, int keyB) {
        Contact c = obtain();
        c.bodyA = a;
        c.bodyB = b;
        c.keyA = keyA;
        c.keyB = keyB;
        c.partA = parts.part(keyA);
        c.partB = b != null ? parts.part(keyB) : 0;
        c.pointCount = 0;
        c.normalX = 0f;
        c.normalY = 0f;
        c.touching = false;
        c.filterDirty = false;
        c.setImpulses(0, 0f, 0f, 0f);
        c.setImpulses(1, 0f, 0f, 0f);
        // Push on the front of both bodies' lists.
        c.prevA = null;
        c.nextA = a.contactList;
        if (a.contactList != null) {
            setPrev(a.contactList, a, c);
        }
        a.contactList = c;
        a.contactCount++;
        c.prevB = null;
        c.nextB = b != null ? b.contactList : null;
        if (b != null && b.contactList != null) {
            setPrev(b.contactList, b, c);
        }
        if (b != null) {
            b.contactList = c;
            b.contactCount++;
        }
        if (count == contacts.length) {
            Contact[] grown = new Contact[count * 2];
            System.arraycopy(contacts, 0, grown, 0, count);
            contacts = grown;
        }
        c.index = count;
        contacts[count++] = c;
        apart.ensure(count);
        apart.clear(c.index);
        if (b != null) {
            pairs.add(PairCounts.parts(keyA, keyB));
        }
        return c;
    }

    /**
     * A contact from the pool. An empty pool is refilled with an eighth of the live count at once:
     * taking one new object per new peak, a world whose contact count wanders near its peak (a pile
     * that keeps tumbling) would go on allocating long after it settled.
     */
    /** The contact a handle names, or null when it has ended. */
    Contact find(long handle) {
        int serial = (int) (handle >>> 32);
        if (serial < 0 || serial >= allCount) {
            return null;
        }
        Contact c = all[serial];
        return c.generation == (int) handle && c.index >= 0 ? c : null;
    }

    private Contact obtain() {
        if (poolCount == 0) {
            int n = Math.max(16, count >> 3);
            if (pool.length < n) {
                pool = new Contact[Math.max(n, 2 * pool.length)];
            }
            for (int i = 0; i < n; i++) {
                Contact c = new Contact();
                if (allCount == all.length) {
                    all = java.util.Arrays.copyOf(all, 2 * allCount);
                }
                c.serial = allCount;
                all[allCount++] = c;
                pool[i] = c;
            }
            poolCount = n;
        }
        return pool[--poolCount];
    }

    private static void setPrev(Contact k, Body b, Contact prev) {
        if (k.bodyA == b) {
            k.prevA = prev;
        } else {
            k.prevB = prev;
        }
    }

    private static void setNext(Contact k, Body b, Contact next) {
        if (k.bodyA == b) {
            k.nextA = next;
        } else {
            k.nextB = next;
        }
    }

    private static void unlink(Contact c, Body b, Contact prev, Contact next) {
        if (prev != null) {
            setNext(prev, b, next);
        } else {
            b.contactList = next;
        }
        if (next != null) {
            setPrev(next, b, prev);
        }
        b.contactCount--;
    }

    void destroy(Contact c) {
        if (c.touching) {
            c.touching = false;
            world.stepData.contactEnded(c);
        }
        pairs.remove(c.bodyB != null ? PairCounts.parts(c.keyA, c.keyB) : PairCounts.segment(c.keyA, c.segmentSlot));
        unlink(c, c.bodyA, c.prevA, c.nextA);
        if (c.bodyB != null) {
            unlink(c, c.bodyB, c.prevB, c.nextB);
        }
        // Swap-remove keeps the array dense; the order stays deterministic.
        int i = c.index;
        Contact last = contacts[--count];
        contacts[i] = last;
        last.index = i;
        apart.move(count, i);
        contacts[count] = null;
        c.index = -1;
        c.reusable = false;
        c.apartGap = 0f;
        c.generation++;
        c.bodyA = null;
        c.bodyB = null;
        c.landscape = null;
        c.segmentSlot = -1;
        c.keyA = -1;
        c.keyB = -1;
        c.prevA = c.nextA = c.prevB = c.nextB = null;
        if (poolCount == pool.length) {
            Contact[] grown = new Contact[poolCount * 2];
            System.arraycopy(pool, 0, grown, 0, poolCount);
            pool = grown;
        }
        pool[poolCount++] = c;
    }

    void destroyContactsOf(Body b) {
        while (b.contactList != null) {
            destroy(b.contactList);
        }
    }

    void markFilterDirty(Body b) {
        for (Contact k = b.contactList; k != null; k = k.next(b)) {
            k.filterDirty = true;
            apart.clear(k.index);
        }
    }

    // ---------------------------------------------------------------------------------------------
    // The landscape

    /**
     * Starts a tick with the world's landscape: contacts with a replaced landscape are dropped, and
     * any change of the segments sends every body back to look for its segments.
     */
    void beginLandscape(Landscape l) {
        // The first call of a tick.
        capacityReached = false;
        if (l != landscape) {
            for (int i = 0; i < count;) {
                if (contacts[i].segmentSlot >= 0) {
                    destroy(contacts[i]);
                } else {
                    i++;
                }
            }
            landscape = l;
            landscapeModCount = l.modCount;
            landscapeEpoch++;
        } else if (l.modCount != landscapeModCount) {
            landscapeModCount = l.modCount;
            landscapeEpoch++;
        }
        l.prepare();
    }

    /**
     * Whether a simulated body must look for its segments although its boxes did not move: the
     * landscape changed, or the body was told to ({@link #forgetLandscape}). Either way it counts as
     * having looked from now on.
     */
    boolean landscapeStale(Body b) {
        boolean stale = isLandscapeStale(b);
        b.landscapeEpoch = landscapeEpoch;
        return stale;
    }

    /** {@link #landscapeStale} without counting as a look: it only reads. */
    boolean isLandscapeStale(Body b) {
        return b.landscapeEpoch != landscapeEpoch;
    }

    /**
     * Creates the missing contacts of a simulated body's part with the segments its proxy's fat box
     * overlaps; called when that box has moved or the body's look is stale ({@link #landscapeStale}).
     * Each part meets the segments near it alone, as it meets other bodies' parts.
     */
    void findLandscapeContacts(Body b, int part, int key, int proxy, BroadPhase broadPhase) {
        if (!b.isDynamic() || b.sensor || landscape.getSegmentCount() == 0) {
            return;
        }
        foundCount = 0;
        landscape.query(broadPhase.getFatMinX(proxy), broadPhase.getFatMinY(proxy), broadPhase.getFatMaxX(proxy),
            broadPhase.getFatMaxY(proxy), this);
        // In slot order, not the index tree's: a segment added far away must not reorder the contacts
        // (and so the solve) of a body here.
        HeapSort.sort(foundSlots, foundCount);
        for (int i = 0; i < foundCount; i++) {
            int slot = (int) foundSlots[i];
            long pair = PairCounts.segment(key, slot);
            if (!pairs.contains(pair) && !full(1)) {
                Contact c = create(b, null, key, -1);
                c.landscape = landscape;
                c.segmentSlot = slot;
                c.segmentStamp = landscape.stampOf(slot);
                pairs.add(pair);
            }
        }
    }

    /** Makes a body look for its segments again when it is next simulated. */
    static void forgetLandscape(Body b) {
        b.landscapeEpoch = -1;
    }

    @Override
    public boolean reportProxy(int slot) {
        if (foundCount == foundSlots.length) {
            foundSlots = Arrays.copyOf(foundSlots, 2 * foundCount);
        }
        foundSlots[foundCount++] = slot;
        return true;
    }

    // ---------------------------------------------------------------------------------------------
    // Each tick

    /** Makes every contact active (no simulation area: every body is simulated). */
    void gatherAll() {
        ensureActive(count);
        System.arraycopy(contacts, 0, active, 0, count);
        activeIsAll = true;
        activeCount = count;
    }

    /**
     * Makes active the contacts of the given simulated bodies, in contact-array order. The work is
     * proportional to those bodies' contacts, not to all contacts.
     */
    void gather(Body[] bodies, int n, long tick) {
        activeCount = 0;
        activeIsAll = false;
        gatherMore(bodies, n, tick);
    }

    /**
     * Appends to the active contacts those of the given bodies not gathered yet this tick (bodies
     * woken during it), in contact-array order.
     *
     * @return where the appended ones start
     */
    int gatherMore(Body[] bodies, int n, long tick) {
        int from = activeCount;
        // The narrowphase reads the indices of the appended contacts only: those before were collided.
        activeIsAll = false;
        int k = 0;
        for (int i = 0; i < n; i++) {
            Body b = bodies[i];
            for (Contact c = b.contactList; c != null; c = c.next(b)) {
                if (c.gathered != tick) {
                    c.gathered = tick;
                    if (k == keys.length) {
                        keys = Arrays.copyOf(keys, 2 * k);
                    }
                    keys[k++] = c.index;
                }
            }
        }
        HeapSort.sort(keys, k);
        ensureActive(from + k);
        for (int i = 0; i < k; i++) {
            int index = (int) keys[i];
            active[from + i] = contacts[index];
            activeIndex[from + i] = index;
        }
        activeCount = from + k;
        return from;
    }

    private void ensureActive(int n) {
        if (active.length < n) {
            active = Arrays.copyOf(active, Math.max(n, 2 * active.length));
            activeIndex = Arrays.copyOf(activeIndex, active.length);
            noPoints = Arrays.copyOf(noPoints, active.length);
        }
    }

    /**
     * Runs the narrowphase on every active contact, dropping those whose fat boxes no longer
     * overlap. The speculative margin grows with the distance the pair can close in sweepTime (the
     * tick times {@link SolverSettings#getSpeculativeSweep()}), so bodies moving several pixels per
     * tick are caught before they overlap.
     *
     * <p>With a worker pool the manifolds are computed by several threads ({@link NarrowPhase}: each
     * writes only its contacts); then this thread, in contact order, asks the filters that must be
     * asked, destroys the contacts that ended and reports touches, so the result and the events are
     * those of one thread.
     */
    void collide(BroadPhase broadPhase, float sweepTime, float speculative, int from) {
        reuseTolerance = Math.min(world.getSolverSettings().getManifoldReuseDistance(), 0.5f * speculative);
        phaseBroadPhase = broadPhase;
        phaseSweepTime = sweepTime;
        phaseSpeculative = speculative;
        if (outcome.length < activeCount) {
            outcome = new byte[Math.max(activeCount, 2 * outcome.length)];
        }
        WorkerPool p = workers;
        if (p != null) {
            p.run(collideTask, from, activeCount, minPart);
        } else {
            collideRange(0, from, activeCount);
        }
        // In the list's order, for the events; a contact that neither died, nor began or ended
        // touching, nor waits for the filter is not read here (the loop over a large pile stayed on
        // one thread and missed the cache on every contact).
        NarrowPhase own = narrow[0];
        int kept = from;
        for (int i = from; i < activeCount; i++) {
            Contact c = active[i];
            active[i] = null;
            byte o = outcome[i];
            if (o == NarrowPhase.FILTER) {
                c.filterDirty = false;
                o = shouldCollide(c.bodyA, c.bodyB) && filterAccepts(c.bodyA, c.bodyB)
                    ? own.collideParts(c, parts, broadPhase, sweepTime, speculative, reuseTolerance) : NarrowPhase.DEAD;
                if (o != NarrowPhase.DEAD) {
                    o = touch(c, speculative);
                    apart.note(c);
                    noPoints[i] = c.pointCount == 0;
                }
            }
            if (o == NarrowPhase.DEAD) {
                destroy(c);
                continue;
            }
            if (o == BEGAN) {
                world.stepData.contactBegan(c);
            } else if (o == ENDED) {
                world.stepData.contactEnded(c);
            }
            noPoints[kept] = noPoints[i];
            active[kept++] = c;
        }
        activeCount = kept;
        phaseBroadPhase = null;
    }

    /**
     * The narrowphase of active contacts [from, to) by one thread: each contact's manifold, touching
     * flag and outcome, no shared state.
     */
    private void collideRange(int worker, int from, int to) {
        NarrowPhase np = narrow[worker];
        BroadPhase broadPhase = phaseBroadPhase;
        float sweepTime = phaseSweepTime;
        float speculative = phaseSpeculative;
        float tolerance = reuseTolerance;
        Contact[] list = active;
        int[] index = activeIsAll ? null : activeIndex;
        byte[] out = outcome;
        boolean[] none = noPoints;
        ApartPairs copies = apart;
        for (int i = from; i < to; i++) {
            int j = index == null ? i : index[i];
            if (copies.isValid(j)) {
                byte o = np.collideApart(copies, j, parts, broadPhase, sweepTime, speculative);
                if (o != NarrowPhase.UNKNOWN) {
                    out[i] = o;
                    none[i] = true;
                    continue;
                }
            }
            Contact c = list[i];
            byte o = c.segmentSlot >= 0 ? np.collideLandscape(c, parts, broadPhase, sweepTime, speculative, tolerance)
                : np.collideBodies(c, parts, broadPhase, sweepTime, speculative, tolerance);
            out[i] = o == NarrowPhase.ALIVE ? touch(c, speculative) : o;
            copies.note(c);
            none[i] = c.pointCount == 0;
        }
    }

    /** Shares the narrowphase with a pool's threads, or not (null). The results are the same either way. */
    void setPool(WorkerPool pool) {
        workers = pool;
        int threads = pool == null ? 1 : pool.getThreadCount();
        if (narrow.length < threads) {
            NarrowPhase[] more = Arrays.copyOf(narrow, threads);
            for (int i = narrow.length; i < threads; i++) {
                more[i] = new NarrowPhase();
            }
            narrow = more;
        }
    }

    /**
     * Leaves out of this tick's solve the contacts the listener refuses (the active list is rebuilt
     * every tick, so they come back next tick), dropping their impulses.
     */
    void preSolve(PreSolveListener listener) {
        int kept = 0;
        for (int i = 0, n = activeCount; i < n; i++) {
            Contact c = active[i];
            active[i] = null;
            if (c.pointCount == 0 || listener.preSolve(c)) {
                noPoints[kept] = noPoints[i];
                active[kept++] = c;
            } else {
                c.setImpulses(0, 0f, 0f, 0f);
                c.setImpulses(1, 0f, 0f, 0f);
            }
        }
        activeCount = kept;
    }

    // Outcomes of a contact that lives on, beside NarrowPhase's: it began or ended touching.
    private static final byte BEGAN = 3;
    private static final byte ENDED = 4;

    /**
     * Starts touching at zero separation, stops beyond the speculative distance: ALIVE, BEGAN or
     * ENDED, for the events, which the caller reports in the list's order.
     */
    private static byte touch(Contact c, float speculative) {
        int n = c.pointCount;
        float gap = n == 0 ? Float.MAX_VALUE : n == 1 ? c.separation0 : Math.min(c.separation0, c.separation1);
        if (!c.touching && gap <= 0f) {
            c.touching = true;
            return BEGAN;
        } else if (c.touching && !(gap <= speculative)) {
            c.touching = false;
            return ENDED;
        }
        return NarrowPhase.ALIVE;
    }

}
