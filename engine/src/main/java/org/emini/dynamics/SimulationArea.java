package org.emini.dynamics;

import org.emini.collision.BroadPhase;
import org.emini.collision.QueryCallback;
import org.emini.internal.HeapSort;
import org.emini.shape.Shape;

/**
 * The world's simulation area and the bodies it simulates this tick.
 *
 * <p>Without an area every dynamic and kinematic body is simulated. With one, the simulated bodies
 * are the dynamic and kinematic bodies whose bounding box overlaps the area, found by querying the broadphase with the
 * area, so the cost follows the bodies inside rather than all bodies. The others are frozen: not
 * integrated, not moved in the broadphase, not collided with each other or the landscape, and
 * seen by the solver as static (index 0), so bodies inside rest on them rather than fall into them.
 * Their velocity is kept for when the area comes back to them.
 */
final class SimulationArea implements QueryCallback {
    private boolean bounded;
    private float minX;
    private float minY;
    private float maxX;
    private float maxY;

    /** The bodies simulated this tick, in world order. */
    Body[] bodies = new Body[16];
    int count;
    private Body[] previous = new Body[16];
    private int previousCount;
    private long[] keys = new long[16];
    private int keyCount;

    private Simulation world;
    private BroadPhase broadPhase;
    private final float[] box = new float[4];

    void set(float minX, float minY, float maxX, float maxY) {
        this.minX = minX;
        this.minY = minY;
        this.maxX = maxX;
        this.maxY = maxY;
        bounded = true;
    }

    void clear() {
        bounded = false;
    }

    boolean isBounded() {
        return bounded;
    }

    float minX() {
        return minX;
    }

    float minY() {
        return minY;
    }

    float maxX() {
        return maxX;
    }

    float maxY() {
        return maxY;
    }

    /**
     * Finds this tick's simulated bodies. Bodies that were simulated last tick lose their solver
     * index and their awake mark first, so a body that left the area counts as static.
     */
    void collect(Simulation w, BroadPhase bp, Body[] all, int allCount) {
        Body[] t = previous;
        previous = bodies;
        bodies = t;
        previousCount = count;
        count = 0;
        for (int i = 0; i < previousCount; i++) {
            Body b = previous[i];
            b.awake = false;
            b.solverIndex = 0;
        }
        if (!bounded) {
            ensure(allCount);
            for (int i = 0; i < allCount; i++) {
                if (!all[i].isStatic() && !all[i].sleeping) {
                    bodies[count++] = all[i];
                }
            }
        } else {
            world = w;
            broadPhase = bp;
            keyCount = 0;
            bp.queryDynamic(minX, minY, maxX, maxY, this);
            world = null;
            broadPhase = null;
            // World order, so the result does not depend on the tree's shape; a multi-shape body
            // is found once per part in the area.
            HeapSort.sort(keys, keyCount);
            ensure(keyCount);
            for (int i = 0; i < keyCount; i++) {
                if (i == 0 || keys[i] != keys[i - 1]) {
                    bodies[count++] = w.getBody((int) keys[i]);
                }
            }
        }
        for (int i = 0; i < count; i++) {
            bodies[i].awake = true;
        }
        for (int i = 0; i < previousCount; i++) {
            Body b = previous[i];
            previous[i] = null;
            if (!b.awake && b.world == w) {
                fitFrozen(b, w, bp);
            }
        }
    }

    /**
     * A body that just stopped being simulated keeps its broadphase boxes until it wakes, but the
     * solver moved it after they were last fitted (at the start of its last tick), possibly out of
     * them: fit each part's again if so, so that queries of the broadphase (this area's,
     * World.queryBodies) find it where it is.
     */
    private void fitFrozen(Body b, Simulation w, BroadPhase bp) {
        Shape shape = b.getShape();
        for (int k = 0; k < b.partKeys.length; k++) {
            ContactManager.part(shape, k).computeAabb(b.x, b.y, b.c, b.s, box);
            int p = w.proxyOf(b, k);
            if (box[0] < bp.getFatMinX(p) || box[1] < bp.getFatMinY(p) || box[2] > bp.getFatMaxX(p)
                || box[3] > bp.getFatMaxY(p)) {
                bp.moveProxy(p, box[0], box[1], box[2], box[3], 0f, 0f);
                ContactManager.forgetLandscape(b);
            }
        }
    }

    @Override
    public boolean reportProxy(int proxyId) {
        Body b = world.bodyOfProxy(proxyId);
        if (b.isStatic() || b.sleeping) {
            return true;
        }
        // The fat box overlaps; the body counts as inside when its own box does.
        b.getShape().computeAabb(b.x, b.y, b.c, b.s, box);
        if (box[0] <= maxX && minX <= box[2] && box[1] <= maxY && minY <= box[3]) {
            if (keyCount == keys.length) {
                keys = java.util.Arrays.copyOf(keys, 2 * keyCount);
            }
            keys[keyCount++] = b.worldIndex;
        }
        return true;
    }

    private void ensure(int n) {
        if (bodies.length < n) {
            int c = Math.max(n, 2 * bodies.length);
            bodies = new Body[c];
            // Still read after the new list is made (fitFrozen).
            previous = java.util.Arrays.copyOf(previous, c);
        }
    }
}
