package org.emini.dynamics;

import java.util.Arrays;

/**
 * Which contacts an impact relax pass visits: those of the bodies that the previous relax pass marked
 * hot (see {@link SolverSettings#getImpactTolerance()}). Scanning every slot for them cost 20 to 80
 * times the contacts solved in a pile that keeps tumbling (the tumbler visited 230,000 slots a tick to
 * solve 10,000). Instead the marked bodies are listed as they are marked, each body's slots are
 * indexed once in a tick that has a hot pass, and the slots of the listed bodies are set in a bitmap
 * read in slot order: the same contacts, in the same order, as the scan.
 *
 * <p>Workers list the bodies they mark in lists of their own; a body is listed once a pass, since
 * the contacts of one colour share no moving body and colours are solved one after the other.
 */
final class HotContacts {
    private int[][] lists = new int[1][16];
    private int[] listed = new int[1];
    // The slots of body b: slots[start[b]] to slots[start[b + 1] − 1].
    private int[] start = new int[17];
    private int[] slots = new int[32];
    private int[] cursor = new int[17];
    private boolean indexed;
    private long[] bits = new long[1];

    /** New slots this tick: the index is built again if a hot pass needs it. */
    void slotsChanged() {
        indexed = false;
    }

    /** Empties the lists before a relax pass, with room for every body in each worker's. */
    void clearLists(int workers, int bodyCount) {
        if (lists.length < workers) {
            lists = Arrays.copyOf(lists, workers);
            listed = new int[workers];
        }
        for (int w = 0; w < lists.length; w++) {
            if (lists[w] == null || lists[w].length < bodyCount) {
                lists[w] = new int[Math.max(bodyCount, 16)];
            }
            listed[w] = 0;
        }
    }

    /** Lists a body the worker marked hot in this pass (once a pass). */
    void list(int worker, int body) {
        lists[worker][listed[worker]++] = body;
    }

    /**
     * Sets the slots of the bodies listed in the last pass, among the count slots whose bodies are
     * n[k * CI + BODY_A] and n[k * CI + BODY_B].
     */
    void select(int[] n, int count, int bodyCount) {
        if (!indexed) {
            index(n, count, bodyCount);
        }
        int words = (count + 63) >>> 6;
        if (bits.length < words) {
            bits = new long[Math.max(words, 2 * bits.length)];
        }
        Arrays.fill(bits, 0, words, 0L);
        long[] b = bits;
        for (int w = 0; w < lists.length; w++) {
            int[] list = lists[w];
            for (int i = 0; i < listed[w]; i++) {
                int body = list[i];
                for (int j = start[body]; j < start[body + 1]; j++) {
                    int k = slots[j];
                    b[k >>> 6] |= 1L << k;
                }
            }
        }
    }

    /** The first selected slot at or after from, or count when none is. */
    int next(int from, int count) {
        int w = from >>> 6;
        int words = (count + 63) >>> 6;
        if (w >= words) {
            return count;
        }
        long x = bits[w] & (-1L << from);
        while (x == 0L) {
            if (++w == words) {
                return count;
            }
            x = bits[w];
        }
        return Math.min((w << 6) + Long.numberOfTrailingZeros(x), count);
    }

    /** The first slot after a selected one that is not selected (at most count). */
    int runEnd(int from, int count) {
        int w = from >>> 6;
        int words = (count + 63) >>> 6;
        long x = ~bits[w] & (-1L << from);
        while (x == 0L) {
            if (++w == words) {
                return count;
            }
            x = ~bits[w];
        }
        return Math.min((w << 6) + Long.numberOfTrailingZeros(x), count);
    }

    private void index(int[] n, int count, int bodyCount) {
        if (start.length < bodyCount + 1) {
            start = new int[Math.max(bodyCount + 1, 2 * start.length)];
            cursor = new int[start.length];
        }
        // Counts first (in start[b + 1]), then their running sum: start[b] is where b's slots begin.
        Arrays.fill(start, 0, bodyCount + 1, 0);
        for (int k = 0; k < count; k++) {
            int ia = n[k * ContactSolver.CI + ContactSolver.BODY_A];
            int ib = n[k * ContactSolver.CI + ContactSolver.BODY_B];
            // Slot 0 (every static body) is never marked.
            if (ia != 0) {
                start[ia + 1]++;
            }
            if (ib != 0 && ib != ia) {
                start[ib + 1]++;
            }
        }
        for (int b = 0; b < bodyCount; b++) {
            start[b + 1] += start[b];
        }
        int total = start[bodyCount];
        if (slots.length < total) {
            slots = new int[Math.max(total, 2 * slots.length)];
        }
        System.arraycopy(start, 0, cursor, 0, bodyCount);
        for (int k = 0; k < count; k++) {
            int ia = n[k * ContactSolver.CI + ContactSolver.BODY_A];
            int ib = n[k * ContactSolver.CI + ContactSolver.BODY_B];
            if (ia != 0) {
                slots[cursor[ia]++] = k;
            }
            if (ib != 0 && ib != ia) {
                slots[cursor[ib]++] = k;
            }
        }
        indexed = true;
    }
}
