package org.emini.dynamics;

import org.emini.collision.BroadPhase;
import org.emini.math.EMath;

/**
 * Keeps a world's broadphase proxies in step with its bodies: one proxy per body, made and dropped
 * with it; each tick, the proxies of the simulated bodies and of the bodies the application moved
 * (the dirty list) are moved; a change of shape, kind or layers re-files the proxy and makes the
 * body look for its landscape segments again.
 */
final class ProxySync {
    private final Simulation world;
    private final BroadPhase broadPhase;
    private final ContactManager contacts;
    private final float[] box = new float[4];
    // Bodies whose pose or shape the application changed since the last tick.
    Body[] dirty = new Body[16];
    int dirtyCount;

    ProxySync(Simulation world, BroadPhase broadPhase, ContactManager contacts) {
        this.world = world;
        this.broadPhase = broadPhase;
        this.contacts = contacts;
    }

    void create(Body b) {
        b.proxyDirty = false;
        ContactManager.forgetLandscape(b);
        b.getShape().computeAabb(b.x, b.y, b.c, b.s, box);
        b.proxyId = broadPhase.createProxy(box[0], box[1], box[2], box[3], b.slot, b.isStatic());
    }

    void destroy(Body b) {
        broadPhase.destroyProxy(b.proxyId);
        b.proxyId = -1;
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

    /** A new shape between ticks: its contacts name the old shape's parts, so they start afresh. */
    void shapeChanged(Body b) {
        contacts.destroyContactsOf(b);
        geometryChanged(b);
        broadPhase.touchProxy(b.proxyId);
        ContactManager.forgetLandscape(b);
    }

    void filterChanged(Body b) {
        contacts.markFilterDirty(b);
        broadPhase.setStatic(b.proxyId, b.isStatic());
        broadPhase.touchProxy(b.proxyId);
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
            b.getShape().computeAabb(b.x, b.y, b.c, b.s, box);
            broadPhase.moveProxy(b.proxyId, box[0], box[1], box[2], box[3], 0f, 0f);
            ContactManager.forgetLandscape(b);
        }
        dirtyCount = 0;
        for (int i = 0; i < simulatedCount; i++) {
            Body b = simulated[i];
            b.proxyDirty = false;
            b.getShape().computeAabb(b.x, b.y, b.c, b.s, box);
            float dx = b.vx * dt;
            float dy = b.vy * dt;
            if (!EMath.isFinite(dx + dy + box[0] + box[1] + box[2] + box[3])) {
                return b;
            }
            boolean moved = broadPhase.moveProxy(b.proxyId, box[0], box[1], box[2], box[3], dx, dy);
            contacts.findLandscapeContacts(b, moved, broadPhase);
        }
        return null;
    }
}
