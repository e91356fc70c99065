package org.emini.dynamics;

import java.util.Arrays;
import org.emini.internal.UnionFind;

/**
 * Sleeping: bodies that have rested long enough stop being simulated, island by island, and wake
 * together. After each solve every simulated body that moved slower than the tolerances for the
 * whole tick adds the tick to its rest time; the simulated bodies joined by contacts with points
 * and by constraints form islands (union–find, in world order, so deterministic), and an island
 * whose every body has rested {@link SolverSettings#getTimeToSleep()} falls asleep: its
 * velocities are zeroed and its bodies, linked in a ring, are left out of the simulation like
 * frozen ones (static to the awake bodies, not integrated, not collided with each other). A ring
 * wakes as a whole: when an awake body's contact with one of its bodies gains points, or the
 * application changes one of its bodies, adds or removes a constraint on it or removes a body
 * touching it.
 */
final class Sleep {
    private boolean enabled;
    private final UnionFind islands = new UnionFind();
    private boolean[] restless = new boolean[16];
    // The last body linked into each resting island's ring, by root.
    private Body[] ringTail = new Body[16];

    boolean isEnabled() {
        return enabled;
    }

    void setEnabled(boolean on, Simulation world) {
        enabled = on;
        if (!on) {
            wakeAll(world);
        }
    }

    /** Wakes the ring of a sleeping body. */
    void wake(Body b) {
        if (!b.sleeping) {
            return;
        }
        Body k = b;
        do {
            Body next = k.sleepNext;
            k.sleeping = false;
            k.sleepTime = 0f;
            k.sleepNext = null;
            k = next;
        } while (k != null && k != b);
    }

    void wakeAll(Simulation world) {
        for (int i = 0, n = world.getBodyCount(); i < n; i++) {
            wake(world.getBody(i));
        }
    }

    /**
     * Wakes the sleeping bodies an awake body's contact has reached (points found this tick).
     *
     * @return whether any woke
     */
    boolean wakeTouched(Contact[] active, int from, int count) {
        boolean woke = false;
        for (int i = from; i < count; i++) {
            Contact c = active[i];
            if (c.pointCount > 0 && c.bodyB != null && (c.bodyA.sleeping != c.bodyB.sleeping)) {
                wake(c.bodyA.sleeping ? c.bodyA : c.bodyB);
                woke = true;
            }
        }
        return woke;
    }

    /** Wakes the bodies touching a body that leaves the world, and its own ring. */
    void wakeNeighbours(Body gone) {
        wake(gone);
        for (Contact c = gone.contactList; c != null; c = c.next(gone)) {
            Body other = c.getOther(gone);
            if (other != null) {
                wake(other);
            }
        }
    }

    void wakeConstrained(Constraint c, Simulation world) {
        int n = c.getBodyCount();
        if (n < 0) {
            wakeAll(world);
            return;
        }
        for (int i = 0; i < n; i++) {
            wake(c.getBody(i));
        }
    }

    /**
     * After a solve: adds the tick to the rest time of the simulated bodies that stayed slow, and
     * puts to sleep the islands that have all rested long enough.
     */
    void afterSolve(Body[] simulated, int count, Contact[] active, int activeCount, Constraint[] constraints,
            int constraintCount, SolverSettings settings, float dt) {
        if (restless.length < count) {
            restless = new boolean[Math.max(count, 2 * restless.length)];
        }
        islands.reset(count);
        float linear = settings.getSleepLinearTolerance();
        float angular = settings.getSleepAngularTolerance();
        float timeToSleep = settings.getTimeToSleep();
        boolean anyReady = false;
        for (int i = 0; i < count; i++) {
            Body b = simulated[i];
            restless[i] = false;
            if (!b.sleepAllowed || b.vx * b.vx + b.vy * b.vy > linear * linear || b.w * b.w > angular * angular) {
                b.sleepTime = 0f;
            } else {
                b.sleepTime += dt;
            }
            anyReady |= b.sleepTime >= timeToSleep;
        }
        if (!anyReady) {
            return;
        }
        for (int i = 0; i < activeCount; i++) {
            Contact c = active[i];
            if (c.pointCount > 0 && c.bodyB != null) {
                union(c.bodyA, c.bodyB);
            }
        }
        for (int i = 0; i < constraintCount; i++) {
            Constraint c = constraints[i];
            int n = c.getBodyCount();
            if (n < 0) {
                // Bodies of a constraint that does not name them stay awake.
                for (int k = 0; k < count; k++) {
                    if (c.concernsBody(simulated[k])) {
                        restless[k] = true;
                    }
                }
                continue;
            }
            Body first = n > 0 ? c.getBody(0) : null;
            for (int k = 1; k < n; k++) {
                union(first, c.getBody(k));
            }
        }
        // An island is restless if any body in it is.
        for (int i = 0; i < count; i++) {
            if (simulated[i].sleepTime < timeToSleep || restless[i]) {
                restless[islands.find(i)] = true;
            }
        }
        // Link each resting island's bodies into a ring, in world order, through its root.
        if (ringTail.length < count) {
            ringTail = new Body[Math.max(count, 2 * ringTail.length)];
        }
        for (int i = 0; i < count; i++) {
            int root = islands.find(i);
            if (restless[root]) {
                continue;
            }
            Body b = simulated[i];
            Body tail = ringTail[root];
            if (tail == null) {
                ringTail[root] = b;
                b.sleepNext = b;
            } else {
                b.sleepNext = tail.sleepNext;
                tail.sleepNext = b;
                ringTail[root] = b;
            }
            b.sleeping = true;
            b.vx = 0f;
            b.vy = 0f;
            b.w = 0f;
        }
        Arrays.fill(ringTail, 0, count, null);
    }

    private void union(Body a, Body b) {
        int ia = indexOf(a);
        int ib = indexOf(b);
        if (ia < 0 || ib < 0) {
            // A body outside the simulation (static, frozen) joins nothing.
            return;
        }
        // The smaller index roots, so the rings come out the same whatever the order.
        islands.union(ia, ib);
    }

    private static int indexOf(Body b) {
        return b.awake ? b.stepIndex : -1;
    }
}
