package org.emini.dynamics;

import org.emini.collision.BroadPhase;
import org.emini.collision.Collider;
import org.emini.collision.Manifold;
import org.emini.collision.PairCallback;

/**
 * Where contacts are born, updated and forgotten.
 *
 * <p>A contact is created when the broadphase reports that two bodies' fat boxes began to overlap
 * and the pair may collide; it is updated by the narrowphase every tick and destroyed when the fat
 * boxes separate or the pair's filter changes. Contact objects are pooled, so steady-state ticking
 * allocates nothing.
 */
final class ContactManager implements PairCallback {
    private final World world;
    private final Collider collider = new Collider();
    private final Manifold manifold = new Manifold();
    Contact[] contacts = new Contact[64];
    int count;
    private Contact[] pool = new Contact[64];
    private int poolCount;

    ContactManager(World world) {
        this.world = world;
    }

    static boolean shouldCollide(Body a, Body b) {
        return (a.isDynamic() || b.isDynamic())
            && a.isInteracting() && b.isInteracting()
            && (a.getCollisionLayers() & b.getCollisionLayers()) == 0;
    }

    @Override
    public void addPair(int slotA, int slotB) {
        Body a = world.bodyInSlot(slotA);
        Body b = world.bodyInSlot(slotB);
        if (a == null || b == null || a == b || !shouldCollide(a, b)) {
            return;
        }
        // Already in contact? Walk the shorter list.
        Body shorter = a.contactCount <= b.contactCount ? a : b;
        Body other = shorter == a ? b : a;
        for (Contact k = shorter.contactList; k != null; k = k.next(shorter)) {
            if (k.getOther(shorter) == other) {
                return;
            }
        }
        create(a, b);
    }

    private void create(Body a, Body b) {
        Contact c = poolCount > 0 ? pool[--poolCount] : new Contact();
        c.bodyA = a;
        c.bodyB = b;
        c.pointCount = 0;
        c.filterDirty = false;
        c.normalImpulse[0] = 0f;
        c.normalImpulse[1] = 0f;
        c.tangentImpulse[0] = 0f;
        c.tangentImpulse[1] = 0f;
        c.maxNormalImpulse[0] = 0f;
        c.maxNormalImpulse[1] = 0f;
        // Push on the front of both bodies' lists.
        c.prevA = null;
        c.nextA = a.contactList;
        if (a.contactList != null) {
            setPrev(a.contactList, a, c);
        }
        a.contactList = c;
        a.contactCount++;
        c.prevB = null;
        c.nextB = b.contactList;
        if (b.contactList != null) {
            setPrev(b.contactList, b, c);
        }
        b.contactList = c;
        b.contactCount++;
        if (count == contacts.length) {
            Contact[] grown = new Contact[count * 2];
            System.arraycopy(contacts, 0, grown, 0, count);
            contacts = grown;
        }
        c.index = count;
        contacts[count++] = c;
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
        unlink(c, c.bodyA, c.prevA, c.nextA);
        unlink(c, c.bodyB, c.prevB, c.nextB);
        // Swap-remove keeps the array dense; the order stays deterministic.
        int i = c.index;
        Contact last = contacts[--count];
        contacts[i] = last;
        last.index = i;
        contacts[count] = null;
        c.index = -1;
        c.bodyA = null;
        c.bodyB = null;
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
        }
    }

    /**
     * Runs the narrowphase on every contact, dropping those whose fat boxes no longer overlap.
     * The speculative margin grows with the distance the pair can close in one tick, so bodies
     * moving several pixels per tick are caught before they overlap.
     */
    void collide(BroadPhase broadPhase, float dt, float speculative) {
        int i = 0;
        while (i < count) {
            Contact c = contacts[i];
            Body a = c.bodyA;
            Body b = c.bodyB;
            if (c.filterDirty) {
                c.filterDirty = false;
                if (!shouldCollide(a, b)) {
                    destroy(c);
                    continue;
                }
            }
            if (!broadPhase.testOverlap(a.proxyId, b.proxyId)) {
                destroy(c);
                continue;
            }
            float margin = speculative + dt * (sweepSpeed(a) + sweepSpeed(b));
            collider.collide(a.getShape(), a.x, a.y, a.c, a.s, b.getShape(), b.x, b.y, b.c, b.s, margin, manifold);
            update(c, manifold);
            i++;
        }
    }

    private static float sweepSpeed(Body b) {
        if (!b.isDynamic()) {
            return 0f;
        }
        float vx = b.vx < 0f ? -b.vx : b.vx;
        float vy = b.vy < 0f ? -b.vy : b.vy;
        float w = b.w < 0f ? -b.w : b.w;
        // |v| ≤ |vx| + |vy|: a cheap, conservative bound.
        return vx + vy + w * b.getShape().getBoundingRadius();
    }

    private static void update(Contact c, Manifold m) {
        int oldCount = c.pointCount;
        float n0 = c.normalImpulse[0];
        float n1 = c.normalImpulse[1];
        float t0 = c.tangentImpulse[0];
        float t1 = c.tangentImpulse[1];
        int id0 = c.id[0];
        int id1 = c.id[1];
        c.pointCount = m.pointCount;
        c.normalX = m.normalX;
        c.normalY = m.normalY;
        c.friction = c.bodyA.getShape().getFriction() * c.bodyB.getShape().getFriction();
        c.restitution = c.bodyA.getShape().getElasticity() * c.bodyB.getShape().getElasticity();
        for (int p = 0; p < m.pointCount; p++) {
            c.pointX[p] = m.pointX[p];
            c.pointY[p] = m.pointY[p];
            c.separation[p] = m.separation[p];
            int key = m.id[p];
            c.id[p] = key;
            // Carry the impulse of the same feature pair over for warm starting.
            float ni = 0f;
            float ti = 0f;
            if (oldCount > 0 && key == id0) {
                ni = n0;
                ti = t0;
            } else if (oldCount > 1 && key == id1) {
                ni = n1;
                ti = t1;
            }
            c.normalImpulse[p] = ni;
            c.tangentImpulse[p] = ti;
            c.maxNormalImpulse[p] = 0f;
        }
    }
}
