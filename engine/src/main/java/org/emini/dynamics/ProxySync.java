package org.emini.dynamics;

import org.emini.collision.BroadPhase;
import org.emini.internal.WorkerPool;
import org.emini.math.EMath;
import org.emini.shape.Shape;

/**
 * Keeps a world's broadphase proxies in step with its bodies: one proxy per part of a body's shape
 * (one for a plain shape), made and dropped with the body, so that contacts exist only for the parts
 * whose fat boxes overlap (a body inside a hollow multi-shape box meets the wall it is near, not all
 * four). Each tick, the proxies of the simulated bodies and of the bodies the application moved (the
 * dirty list) are moved; a change of shape, kind or layers re-files the proxies and makes the body
 * look for its landscape segments again.
 */
final class ProxySync {
    private final Simulation world;
    private final BroadPhase broadPhase;
    private final ContactManager contacts;
    private final PartKeys keys;
    private final float[] box = new float[4];
    // Bodies whose pose or shape the application changed since the last tick.
    Body[] dirty = new Body[16];
    int dirtyCount;
    /** Per simulated body, whether its proxy stays as it is this tick ({@link #markStaying}). */
    private boolean[] staying = new boolean[8];
    private WorkerPool pool;
    private int minBodies = Solver.MIN_BODIES;
    // What markTask reads, and a box per part.
    private Body[] markList;
    private float markDt;
    private float[][] partBox = {box};
    private final WorkerPool.RangeTask markTask = new WorkerPool.RangeTask() {
        @Override
        public void run(int part, int from, int to) {
            markStaying(markList, from, to, markDt, partBox[part]);
        }
    };

    ProxySync(Simulation world, BroadPhase broadPhase, ContactManager contacts, PartKeys keys) {
        this.world = world;
        this.broadPhase = broadPhase;
        this.contacts = contacts;
        this.keys = keys;
    }

    /** Shares the look at the simulated bodies with a pool's threads, or not (null). */
    void setPool(WorkerPool pool) {
        this.pool = pool;
        partBox = new float[pool == null ? 1 : pool.getThreadCount()][];
        partBox[0] = box;
        for (int w = 1; w < partBox.length; w++) {
            partBox[w] = new float[4];
        }
    }

    /** The fewest bodies given to a thread (tests split every range with 1). */
    void setMinParallelPart(int bodies) {
        minBodies = bodies;
    }

    /** Gives each part of the body's shape a key and a proxy, in part order. */
    void create(Body b) {
        b.proxyDirty = false;
        ContactManager.forgetLandscape(b);
        Shape shape = b.getShape();
        int n = ContactManager.partCount(shape);
        if (b.partKeys.length != n) {
            b.partKeys = new int[n];
        }
        boolean isStatic = b.isStatic();
        for (int k = 0; k < n; k++) {
            ContactManager.part(shape, k).computeAabb(b.x, b.y, b.c, b.s, box);
            int key = keys.add(b, k);
            keys.setProxy(key, broadPhase.createProxy(box[0], box[1], box[2], box[3], key, isStatic));
            b.partKeys[k] = key;
        }
    }

    void destroy(Body b) {
        int[] partKeys = b.partKeys;
        for (int k = 0; k < partKeys.length; k++) {
            broadPhase.destroyProxy(keys.proxy(partKeys[k]));
            keys.remove(partKeys[k]);
            partKeys[k] = -1;
        }
        b.proxyDirty = false;
    }

    /** Puts a body the application moved or reshaped on the dirty list, once. */
    void geometryChanged(Body b) {
        if (!b.proxyDirty) {
            b.proxyDirty = true;
            if (dirtyCount == dirty.length) {
                dirty = java.util.Arrays.copyOf(dirty, 2 * dirtyCount);
            }
            dirty[dirtyCount++] = b;
        }
    }

    /**
     * A new shape between ticks: its contacts name the old shape's parts, so they start afresh. With
     * as many parts as before the proxies are kept (and moved next tick); otherwise they are made anew.
     */
    void shapeChanged(Body b) {
        contacts.destroyContactsOf(b);
        if (ContactManager.partCount(b.getShape()) == b.partKeys.length) {
            geometryChanged(b);
            for (int key : b.partKeys) {
                broadPhase.touchProxy(keys.proxy(key));
            }
        } else {
            destroy(b);
            create(b);
        }
        ContactManager.forgetLandscape(b);
    }

    void filterChanged(Body b) {
        contacts.markFilterDirty(b);
        boolean isStatic = b.isStatic();
        for (int key : b.partKeys) {
            int p = keys.proxy(key);
            broadPhase.setStatic(p, isStatic);
            broadPhase.touchProxy(p);
        }
        ContactManager.forgetLandscape(b);
    }

    /**
     * Moves the proxies of the bodies the application moved and of the simulated bodies (those
     * stretched by their coming displacement), and finds the simulated bodies' landscape contacts.
     *
     * @return null, or a simulated body whose box or displacement is not finite (nothing after it moved)
     */
    Body update(Body[] simulated, int simulatedCount, float margin, float dt) {
        // A changed SolverSettings.setAabbMargin re-fattens every box (nothing when unchanged).
        broadPhase.setMargin(margin);
        float[] box = this.box;
        for (int i = 0; i < dirtyCount; i++) {
            Body b = dirty[i];
            dirty[i] = null;
            if (b.world != world || !b.proxyDirty || b.awake) {
                continue;
            }
            b.proxyDirty = false;
            Shape shape = b.getShape();
            for (int k = 0; k < b.partKeys.length; k++) {
                ContactManager.part(shape, k).computeAabb(b.x, b.y, b.c, b.s, box);
                broadPhase.moveProxy(keys.proxy(b.partKeys[k]), box[0], box[1], box[2], box[3], 0f, 0f);
            }
            ContactManager.forgetLandscape(b);
        }
        dirtyCount = 0;
        if (staying.length < simulatedCount) {
            staying = new boolean[Math.max(simulatedCount, 2 * staying.length)];
        }
        markList = simulated;
        markDt = dt;
        if (pool != null) {
            pool.run(markTask, 0, simulatedCount, minBodies);
        } else {
            markStaying(simulated, 0, simulatedCount, dt, box);
        }
        markList = null;
        for (int i = 0; i < simulatedCount; i++) {
            if (staying[i]) {
                continue;
            }
            Body b = simulated[i];
            b.proxyDirty = false;
            boolean lookAgain = contacts.landscapeStale(b);
            int[] partKeys = b.partKeys;
            if (partKeys.length == 1) {
                if (!movePart(b, b.getShape(), partKeys[0], 0, b.vx * dt, b.vy * dt, lookAgain)) {
                    return b;
                }
                continue;
            }
            Shape shape = b.getShape();
            for (int k = 0; k < partKeys.length; k++) {
                // A part moves with the body's velocity at its centroid: the parts of a spinning body
                // move although its centre may not.
                Shape part = ContactManager.part(shape, k);
                float lx = part.getCentroidX();
                float ly = part.getCentroidY();
                float rx = b.c * lx - b.s * ly;
                float ry = b.s * lx + b.c * ly;
                if (!movePart(b, part, partKeys[k], k, (b.vx - b.w * ry) * dt, (b.vy + b.w * rx) * dt, lookAgain)) {
                    return b;
                }
            }
        }
        return null;
    }

    /**
     * Marks the bodies [from, to) of the simulated list for which the loop in {@link #update} would
     * change nothing: one part, not moved by the application, landscape look not stale, a finite box
     * whose proxy stays. It only reads, so ranges may run on different threads (each with its own box).
     */
    private void markStaying(Body[] simulated, int from, int to, float dt, float[] box) {
        boolean[] marks = staying;
        for (int i = from; i < to; i++) {
            Body b = simulated[i];
            int[] partKeys = b.partKeys;
            boolean stays = false;
            if (partKeys.length == 1 && !b.proxyDirty && !contacts.isLandscapeStale(b)) {
                float dx = b.vx * dt;
                float dy = b.vy * dt;
                stays = finiteBox(b, b.getShape(), dx, dy, box)
                    && broadPhase.keepsBox(keys.proxy(partKeys[0]), box[0], box[1], box[2], box[3], dx, dy);
            }
            marks[i] = stays;
        }
    }

    /** Puts a part's tight box into {@code box}; false when it or the displacement is not finite. */
    private static boolean finiteBox(Body b, Shape part, float dx, float dy, float[] box) {
        part.computeAabb(b.x, b.y, b.c, b.s, box);
        return EMath.isFinite(dx + dy + box[0] + box[1] + box[2] + box[3]);
    }

    /** Moves one part's proxy and finds its landscape contacts; false when its box or displacement is not finite. */
    private boolean movePart(Body b, Shape part, int key, int k, float dx, float dy, boolean lookAgain) {
        float[] box = this.box;
        if (!finiteBox(b, part, dx, dy, box)) {
            return false;
        }
        int proxy = keys.proxy(key);
        if (broadPhase.moveProxy(proxy, box[0], box[1], box[2], box[3], dx, dy) || lookAgain) {
            contacts.findLandscapeContacts(b, k, key, proxy, broadPhase);
        }
        return true;
    }
}
