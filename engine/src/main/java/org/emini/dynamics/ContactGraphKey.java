package org.emini.dynamics;

import static org.emini.dynamics.SolverBodies.II;
import static org.emini.dynamics.SolverBodies.IM;
import static org.emini.dynamics.SolverBodies.STRIDE;

/**
 * What the contact solver's colouring depends on, kept from one tick to the next: per contact its
 * bodies' solver slots (or none when it does not touch, or has no body B), per body whether its
 * inverse mass is zero and whether it moves. The colouring is a function of these alone, so a tick
 * whose key equals the last one's may keep the last colouring; in a settled pile that is every tick,
 * and the colouring's breadth-first search and colour search then cost nothing.
 */
final class ContactGraphKey {
    private int[] pairs = new int[32];
    private byte[] kinds = new byte[16];
    private int contactCount = -1;
    private int bodyCount = -1;

    /**
     * Records this tick's key.
     *
     * @return true when it equals the key recorded before (and that one was not {@link #forget forgotten})
     */
    boolean update(Contact[] all, int contactCount, SolverBodies bodies) {
        float[] st = bodies.state;
        int bodyTotal = bodies.count;
        boolean same = contactCount == this.contactCount && bodyTotal == this.bodyCount;
        if (pairs.length < 2 * contactCount) {
            pairs = new int[Math.max(2 * contactCount, 2 * pairs.length)];
            same = false;
        }
        if (kinds.length < bodyTotal) {
            kinds = new byte[Math.max(bodyTotal, 2 * kinds.length)];
            same = false;
        }
        int[] p = pairs;
        for (int ci = 0; ci < contactCount; ci++) {
            Contact c = all[ci];
            int a = c.pointCount == 0 ? -1 : c.bodyA.solverIndex;
            int b = c.bodyB == null ? -1 : c.bodyB.solverIndex;
            if (p[2 * ci] != a || p[2 * ci + 1] != b) {
                same = false;
                p[2 * ci] = a;
                p[2 * ci + 1] = b;
            }
        }
        byte[] k = kinds;
        for (int i = 0; i < bodyTotal; i++) {
            float im = st[i * STRIDE + IM];
            float ii = st[i * STRIDE + II];
            byte kind = (byte) ((im == 0f ? 1 : 0) | (im != 0f || ii != 0f ? 2 : 0));
            if (k[i] != kind) {
                same = false;
                k[i] = kind;
            }
        }
        this.contactCount = contactCount;
        this.bodyCount = bodyTotal;
        return same;
    }

    /** Makes the next {@link #update} answer false (the colouring it guards was lost). */
    void forget() {
        contactCount = -1;
    }
}
