package org.emini.dynamics;

import static org.emini.dynamics.SolverBodies.II;
import static org.emini.dynamics.SolverBodies.IM;
import static org.emini.dynamics.SolverBodies.STRIDE;

/**
 * What the contact solver's colouring depends on, kept from one tick to the next: per contact its
 * bodies' solver slots (or none when it does not touch, or has no body B), per body whether its
 * inverse mass is zero and whether it moves. The colouring is a function of these alone, so a tick
 * whose key equals the last one's may keep the last colouring; in a settled pile that is every tick,
 * and the colouring's breadth-first search and colour search then cost nothing. A graph that keeps
 * changing pays only the comparison, which stops at the first difference, and the recording
 * ({@link #begin}, {@link #body}) as the colouring walks the bodies.
 *
 * <p>{@link #read} takes the contacts' part of the key in one pass over the contact objects, and the
 * colouring reads it from here ({@link #first(int)}, {@link #second(int)}): the objects lie
 * scattered in memory, and the colouring's four passes over them missed the cache on each contact
 * (9 ms of a 67 ms tick at 20,000 bodies; 4 ms with the one pass).
 */
final class ContactGraphKey {
    private int[] pairs = new int[32];
    // This tick's pairs, as read.
    private int[] current = new int[32];
    private byte[] kinds = new byte[16];
    private int contactCount = -1;
    private int bodyCount = -1;

    /** The key of a contact's first body: its slot, or −1 when it does not touch. */
    static int first(Contact c) {
        return c.pointCount == 0 ? -1 : c.bodyA.solverIndex;
    }

    /** The key of a contact's second body: its slot, or −1 for a landscape contact. */
    static int second(Contact c) {
        return c.bodyB == null ? -1 : c.bodyB.solverIndex;
    }

    /** The key of a body's slot: bit 0 for zero inverse mass, bit 1 when it moves. */
    static byte kind(float[] st, int slot) {
        float im = st[slot * STRIDE + IM];
        float ii = st[slot * STRIDE + II];
        return (byte) ((im == 0f ? 1 : 0) | (im != 0f || ii != 0f ? 2 : 0));
    }

    /**
     * Reads this tick's pairs ({@link #first(Contact)}, {@link #second(Contact)} of each contact). A
     * contact the narrowphase left without points is (−1, −1), without reading it: the colouring
     * passes over a contact that does not touch, whatever its second body.
     */
    void read(Contact[] all, boolean[] noPoints, int contactCount) {
        if (current.length < 2 * contactCount) {
            current = new int[Math.max(2 * contactCount, 2 * current.length)];
        }
        int[] p = current;
        for (int ci = 0; ci < contactCount; ci++) {
            if (noPoints[ci]) {
                p[2 * ci] = -1;
                p[2 * ci + 1] = -1;
                continue;
            }
            Contact c = all[ci];
            p[2 * ci] = first(c);
            p[2 * ci + 1] = second(c);
        }
    }

    /** Contact ci's first body as read this tick: its slot, or −1 when it does not touch. */
    int first(int ci) {
        return current[2 * ci];
    }

    /** Contact ci's second body as read this tick: its slot, or −1 for a landscape contact. */
    int second(int ci) {
        return current[2 * ci + 1];
    }

    /** Whether this tick's graph ({@link #read}) is the one recorded last (false when none is recorded). */
    boolean matches(int contactCount, SolverBodies bodies) {
        int bodyTotal = bodies.count;
        if (contactCount != this.contactCount || bodyTotal != this.bodyCount) {
            return false;
        }
        float[] st = bodies.state;
        byte[] k = kinds;
        for (int i = 0; i < bodyTotal; i++) {
            if (k[i] != kind(st, i)) {
                return false;
            }
        }
        int[] p = pairs;
        int[] now = current;
        for (int i = 0; i < 2 * contactCount; i++) {
            if (p[i] != now[i]) {
                return false;
            }
        }
        return true;
    }

    /** Records this tick's pairs ({@link #read}) for a graph of these sizes; {@link #body} fills in the bodies. */
    void begin(int contactCount, int bodyCount) {
        if (pairs.length < 2 * contactCount) {
            pairs = new int[Math.max(2 * contactCount, 2 * pairs.length)];
        }
        System.arraycopy(current, 0, pairs, 0, 2 * contactCount);
        if (kinds.length < bodyCount) {
            kinds = new byte[Math.max(bodyCount, 2 * kinds.length)];
        }
        this.contactCount = contactCount;
        this.bodyCount = bodyCount;
    }

    /** Records a body's {@link #kind}. */
    void body(int slot, byte kind) {
        kinds[slot] = kind;
    }

    /** Makes the next {@link #matches} answer false (the colouring it guards was lost). */
    void forget() {
        contactCount = -1;
    }
}
