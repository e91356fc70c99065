package org.emini.dynamics;

import java.util.Arrays;
import org.emini.internal.UnionFind;

/**
 * The contact solve's slots laid out for threads by island: the moving bodies that contacts join
 * into one group (static and kinematic bodies join nothing, since no impulse changes them). Two
 * islands share no body a pass writes, so their contacts may be solved in either order, or at once,
 * with the same result to the bit; within an island the slots keep the colouring's order (colour by
 * colour, the contacts' order within a colour), so the results are those of the colour-major layout.
 *
 * <p>Large islands (more than {@link #SMALL_SHARE} of the solved contacts) stay colour by colour at
 * the front, where a pass splits each colour among the threads and waits at its end; the small ones
 * follow, island by island, and a pass hands each thread a run of whole islands with one wait for
 * all: ten separate pyramids make 24 colours, so 24 waits a pass laid out by colour, and one by island.
 */
final class SolveIslands {
    /** An island of at most this share of the solved contacts is small (laid out whole). */
    static final int SMALL_SHARE = 8;

    // Body slots joined by the contacts between moving bodies.
    private final UnionFind joined = new UnionFind();
    // Per root body: its island's contacts, and its small island's index + 1 (0: none given, or large).
    private int[] size = new int[16];
    private int[] index = new int[16];
    // Per contact: a moving body of it, then its small island (−1: large).
    private int[] anchor = new int[16];
    // The solved contacts, colour-major.
    private int[] order = new int[16];
    // Per small island: its first slot; islandStart[islands] is the slot count.
    private int[] islandStart = new int[2];
    // Per colour, then per small island: the next slot to give.
    private int[] fill = new int[2];
    // Per colour: where its contacts start in order.
    private int[] byColour = new int[2];
    /** Small islands of the last layout. */
    int islands;
    /** The first slot of the small islands, after a {@link #layout} that laid some out. */
    int smallStart;
    // Per part of a split pass: its first island; split[parts] = islands.
    private int[] split = new int[3];
    private int parts;

    /** Starts a layout of contactCount contacts among bodyCount body slots, each body alone. */
    void begin(int bodyCount, int contactCount) {
        if (size.length < bodyCount) {
            int n = Math.max(bodyCount, 2 * size.length);
            size = new int[n];
            index = new int[n];
        }
        joined.reset(bodyCount);
        if (anchor.length < contactCount) {
            int n = Math.max(contactCount, 2 * anchor.length);
            anchor = new int[n];
            order = new int[n];
        }
        for (int i = 0; i < bodyCount; i++) {
            size[i] = 0;
            index[i] = 0;
        }
    }

    /** Contact ci is solved, with moving body a (and b, or −1 when b does not move). */
    void contact(int ci, int a, int b) {
        anchor[ci] = a;
        if (b >= 0) {
            joined.union(a, b);
        }
    }

    /**
     * Turns colours into slots: colourOf[ci] is contact ci's colour (0 to {@code colours}, the last
     * the overflow group; −1 when it is not solved) and becomes its slot. colourStart receives the
     * large islands' colour starts (colourStart[colours + 1] is {@link #smallStart}); the small islands
     * follow, each colour by colour. Returns the slot count, or −1 (colourOf and colourStart
     * untouched) when every island is large: the colour-major layout is then the one.
     */
    int layout(int[] colourOf, int contactCount, int[] colourStart, int colours) {
        int solved = 0;
        for (int ci = 0; ci < contactCount; ci++) {
            if (colourOf[ci] >= 0) {
                anchor[ci] = joined.find(anchor[ci]);
                size[anchor[ci]]++;
                solved++;
            }
        }
        int limit = solved / SMALL_SHARE;
        islands = 0;
        for (int ci = 0; ci < contactCount; ci++) {
            if (colourOf[ci] < 0) {
                continue;
            }
            int r = anchor[ci];
            if (size[r] > limit) {
                anchor[ci] = -1;
                continue;
            }
            if (index[r] == 0) {
                if (islandStart.length < islands + 2) {
                    islandStart = Arrays.copyOf(islandStart, 2 * (islands + 2));
                }
                index[r] = ++islands;
                islandStart[islands] = size[r];
            }
            anchor[ci] = index[r] - 1;
        }
        parts = 0;
        if (islands == 0) {
            return -1;
        }
        // Colour sizes to starts: of the large islands' contacts (colourStart), and of all (byColour).
        if (byColour.length < colours + 2) {
            byColour = new int[colours + 2];
        }
        int[] all = byColour;
        for (int c = 0; c <= colours + 1; c++) {
            colourStart[c] = 0;
            all[c] = 0;
        }
        for (int ci = 0; ci < contactCount; ci++) {
            int colour = colourOf[ci];
            if (colour >= 0) {
                all[colour + 1]++;
                if (anchor[ci] < 0) {
                    colourStart[colour + 1]++;
                }
            }
        }
        for (int c = 1; c <= colours + 1; c++) {
            all[c] += all[c - 1];
            colourStart[c] += colourStart[c - 1];
        }
        // Every solved contact in colour-major order, the contacts' order within a colour.
        for (int ci = 0; ci < contactCount; ci++) {
            int colour = colourOf[ci];
            if (colour >= 0) {
                order[all[colour]++] = ci;
            }
        }
        smallStart = colourStart[colours + 1];
        islandStart[0] = smallStart;
        for (int i = 1; i <= islands; i++) {
            islandStart[i] += islandStart[i - 1];
        }
        // Slots in that order: so each island, and the large ones together, stay colour-major.
        if (fill.length < islands + colours + 1) {
            fill = new int[Math.max(islands + colours + 1, 2 * fill.length)];
        }
        System.arraycopy(colourStart, 0, fill, 0, colours + 1);
        System.arraycopy(islandStart, 0, fill, colours + 1, islands);
        for (int s = 0; s < solved; s++) {
            int ci = order[s];
            int island = anchor[ci];
            colourOf[ci] = island < 0 ? fill[colourOf[ci]]++ : fill[colours + 1 + island]++;
        }
        return solved;
    }

    /** Forgets the last layout's runs: a colouring that does not lay out islands has none. */
    void clear() {
        islands = 0;
        parts = 0;
    }

    /**
     * Splits the small islands into at most {@code threads} runs of whole islands of about equal
     * contact counts, and returns the runs' count: 0 when sharing them would not pay (fewer than two
     * runs, or fewer than {@code minPart} contacts a run), and the small islands run on one thread.
     */
    int split(int threads, int minPart) {
        int p = Math.min(threads, islands);
        int total = islands == 0 ? 0 : islandStart[islands] - smallStart;
        if (p < 2 || total < p * minPart) {
            parts = 0;
            return 0;
        }
        if (split.length < p + 1) {
            split = new int[p + 1];
        }
        split[0] = 0;
        int island = 0;
        for (int k = 1; k < p; k++) {
            long target = smallStart + (long) total * k / p;
            // The island boundary nearest the target, after the previous one.
            while (island < islands && islandStart[island + 1] <= target) {
                island++;
            }
            if (island < islands && islandStart[island + 1] - target < target - islandStart[island]) {
                island++;
            }
            split[k] = Math.max(island, split[k - 1]);
        }
        split[p] = islands;
        parts = p;
        return p;
    }

    /** The runs of the last {@link #split} (0: none, the small islands, if any, run on one thread). */
    int parts() {
        return parts;
    }

    /** The first slot of run k of the last {@link #split} (k = parts: one past the last). */
    int runStart(int k) {
        return islandStart[split[k]];
    }
}
