package org.emini.dynamics;

import org.emini.collision.BroadPhase;
import org.emini.collision.QueryCallback;
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
    // The sweep: the rectangle moves by (dx, dy); boxes are grown by pad against rounding.
    private boolean swept;
    private float dx;
    private float dy;
    private float pad;

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
        this.dx = dx;
        this.dy = dy;
        swept = dx != 0f || dy != 0f;
        pad = swept ? 1e-6f * (Math.abs(minX) + Math.abs(minY) + Math.abs(maxX) + Math.abs(maxY) + Math.abs(dx)
            + Math.abs(dy)) : 0f;
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
        bp.query(Math.min(minX, minX + dx) - pad, Math.min(minY, minY + dy) - pad, Math.max(maxX, maxX + dx) + pad,
            Math.max(maxY, maxY + dy) + pad, this);
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
        if (swept ? sweepMeets(box) : box[0] <= maxX && minX <= box[2] && box[1] <= maxY && minY <= box[3]) {
            if (count == found.length) {
                found = java.util.Arrays.copyOf(found, 2 * count);
            }
            found[count++] = b.worldIndex;
        }
    }

    /** Whether the rectangle, moved by t·(dx, dy) for some t in [0, 1], meets the (padded) box. */
    private boolean sweepMeets(float[] b) {
        float lo = 0f;
        float hi = 1f;
        // Per axis, the t where [min + t·d, max + t·d] overlaps [b0 − pad, b1 + pad].
        for (int axis = 0; axis < 2; axis++) {
            float qMin = axis == 0 ? minX : minY;
            float qMax = axis == 0 ? maxX : maxY;
            float d = axis == 0 ? dx : dy;
            float bMin = b[axis] - pad;
            float bMax = b[axis + 2] + pad;
            if (d == 0f) {
                if (qMin > bMax || bMin > qMax) {
                    return false;
                }
                continue;
            }
            float enter = (bMin - qMax) / d;
            float leave = (bMax - qMin) / d;
            if (d < 0f) {
                float swap = enter;
                enter = leave;
                leave = swap;
            }
            lo = Math.max(lo, enter);
            hi = Math.min(hi, leave);
            if (lo > hi) {
                return false;
            }
        }
        return true;
    }
}
