package org.emini.dynamics;

import org.emini.collision.BroadPhase;
import org.emini.collision.QueryCallback;
import org.emini.internal.HeapSort;

/**
 * {@link Simulation#queryBodies}: the bodies whose current box overlaps a rectangle, in world order.
 *
 * <p>The last tick's simulated bodies are tested one by one (the solver moved them after their
 * broadphase boxes were last fitted), the bodies the application moved since are tested from the
 * dirty list, and all others (static and frozen bodies) are found through the broadphase, so bodies
 * standing still far away cost nothing.
 */
final class BodyQuery implements QueryCallback {
    private final float[] box = new float[4];
    private long[] found = new long[16];
    private int count;
    private Simulation world;
    private BroadPhase broadPhase;
    private float minX;
    private float minY;
    private float maxX;
    private float maxY;

    void run(Simulation w, BroadPhase bp, SimulationArea area, Body[] dirty, int dirtyCount, float minX, float minY,
            float maxX, float maxY, QueryCallback out) {
        this.minX = minX;
        this.minY = minY;
        this.maxX = maxX;
        this.maxY = maxY;
        count = 0;
        for (int i = 0; i < area.count; i++) {
            Body b = area.bodies[i];
            if (b.awake && b.world == w) {
                test(b);
            }
        }
        for (int i = 0; i < dirtyCount; i++) {
            Body b = dirty[i];
            if (b.proxyDirty && !b.awake && b.world == w) {
                test(b);
            }
        }
        world = w;
        broadPhase = bp;
        bp.query(minX, minY, maxX, maxY, this);
        world = null;
        broadPhase = null;
        // World order, each body once (a body re-added to the world may be listed dirty twice).
        HeapSort.sort(found, count);
        for (int i = 0; i < count; i++) {
            if ((i == 0 || found[i] != found[i - 1]) && !out.reportProxy((int) found[i])) {
                break;
            }
        }
    }

    @Override
    public boolean reportProxy(int proxyId) {
        Body b = world.bodyInSlot(broadPhase.getUserData(proxyId));
        if (b != null && !b.awake && !b.proxyDirty) {
            test(b);
        }
        return true;
    }

    private void test(Body b) {
        b.getShape().computeAabb(b.x, b.y, b.c, b.s, box);
        if (box[0] <= maxX && minX <= box[2] && box[1] <= maxY && minY <= box[3]) {
            if (count == found.length) {
                found = java.util.Arrays.copyOf(found, 2 * count);
            }
            found[count++] = b.worldIndex;
        }
    }
}
