package org.emini.dynamics;

import org.emini.collision.BroadPhase;
import org.emini.collision.QueryCallback;
import org.emini.collision.SweptBox;
import org.emini.internal.HeapSort;

/**
 * {@link Simulation#queryBodies}: the bodies whose current box overlaps a rectangle, in world order;
 * for the world's casts ({@code WorldQuery}), the bodies whose box a rectangle meets as it is swept
 * along a translation (a ray: a point swept).
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
    // The sweep, when the rectangle moves (the world's casts).
    private final SweptBox sweep = new SweptBox();
    private boolean swept;

    void run(Simulation w, BroadPhase bp, SimulationArea area, Body[] dirty, int dirtyCount, float minX, float minY,
            float maxX, float maxY, QueryCallback out) {
        runSwept(w, bp, area, dirty, dirtyCount, minX, minY, maxX, maxY, 0f, 0f, out);
    }

    /**
     * Like {@link #run}, for a rectangle swept by (dx, dy): the bodies whose box it meets on the way
     * (a superset by a few float roundings, so that no body an exact test would hit is left out).
     */
    void runSwept(Simulation w, BroadPhase bp, SimulationArea area, Body[] dirty, int dirtyCount, float minX,
            float minY, float maxX, float maxY, float dx, float dy, QueryCallback out) {
        this.minX = minX;
        this.minY = minY;
        this.maxX = maxX;
        this.maxY = maxY;
        swept = dx != 0f || dy != 0f;
        sweep.set(minX, minY, maxX, maxY, dx, dy);
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
        if (swept) {
            bp.querySwept(sweep, this);
        } else {
            bp.query(minX, minY, maxX, maxY, this);
        }
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
        // A multi-shape body comes once per part near the box; the list drops the repeats.
        Body b = world.bodyOfProxy(proxyId);
        if (!b.awake && !b.proxyDirty) {
            test(b);
        }
        return true;
    }

    private void test(Body b) {
        b.getShape().computeAabb(b.x, b.y, b.c, b.s, box);
        if (swept ? sweep.meets(box[0], box[1], box[2], box[3]) : box[0] <= maxX && minX <= box[2] && box[1] <= maxY && minY <= box[3]) {
            if (count == found.length) {
                found = java.util.Arrays.copyOf(found, 2 * count);
            }
            found[count++] = b.worldIndex;
        }
    }
}
