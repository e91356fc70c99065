package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;

/**
 * {@link SolveIslands}' layout keeps the results of the colour-major one: every solved contact gets
 * a slot of its own; the large islands' contacts come first, colour by colour; each small island's
 * contacts are contiguous and, like the large ones, in colour order with the contacts' order within
 * a colour (so each body meets its contacts in the order it would have), and two islands never share
 * a moving body. The split hands each thread whole islands. When every island is large the layout
 * leaves the colours' one as it is.
 */
class SolveIslandsProperties {
    private static final int COLOURS = 6;

    @Property(tries = 300)
    void theLayoutKeepsEachBodysOrderAndIslandsWhole(@ForAll("seeds") long seed,
            @ForAll @IntRange(min = 2, max = 40) int bodies, @ForAll @IntRange(min = 0, max = 80) int contactCount,
            @ForAll @IntRange(min = 1, max = 4) int threads) {
        java.util.Random random = new java.util.Random(seed);
        // Body 0 and every seventh do not move (static or kinematic): they join nothing.
        int[] a = new int[contactCount];
        int[] b = new int[contactCount];
        int[] colourOf = new int[contactCount];
        SolveIslands islands = new SolveIslands();
        islands.begin(bodies, contactCount);
        for (int ci = 0; ci < contactCount; ci++) {
            a[ci] = random.nextInt(bodies);
            b[ci] = random.nextInt(bodies);
            boolean movesA = moves(a[ci]);
            boolean movesB = moves(b[ci]);
            if (!movesA && !movesB || random.nextInt(10) == 0) {
                colourOf[ci] = -1;
                continue;
            }
            colourOf[ci] = random.nextInt(COLOURS + 1);
            islands.contact(ci, movesA ? a[ci] : b[ci], movesA && movesB ? b[ci] : -1);
        }
        int[] colours = colourOf.clone();
        int[] colourStart = new int[COLOURS + 2];
        int count = islands.layout(colourOf, contactCount, colourStart, COLOURS);
        if (count < 0) {
            // Every island large: the colour-major layout stands, untouched.
            assertEquals(0, islands.islands);
            assertEquals(java.util.Arrays.toString(colours), java.util.Arrays.toString(colourOf));
            assertEquals(0, islands.split(threads, 1));
            return;
        }
        assertTrue(islands.islands > 0);

        // A slot each, and the slot count is the solved count.
        int[] contactAt = new int[count];
        java.util.Arrays.fill(contactAt, -1);
        int solved = 0;
        for (int ci = 0; ci < contactCount; ci++) {
            if (colours[ci] < 0) {
                assertEquals(-1, colourOf[ci]);
                continue;
            }
            solved++;
            assertTrue(colourOf[ci] >= 0 && colourOf[ci] < count);
            assertEquals(-1, contactAt[colourOf[ci]], "two contacts in one slot");
            contactAt[colourOf[ci]] = ci;
        }
        assertEquals(solved, count);
        // The large islands: colour by colour, as colourStart says.
        assertEquals(islands.smallStart, colourStart[COLOURS + 1]);
        for (int c = 0; c <= COLOURS; c++) {
            for (int k = colourStart[c]; k < colourStart[c + 1]; k++) {
                assertEquals(c, colours[contactAt[k]]);
            }
        }
        // Each moving body meets its contacts in colour-major order, the contacts' order within a colour.
        for (int body = 0; body < bodies; body++) {
            if (!moves(body)) {
                continue;
            }
            List<Integer> seen = new ArrayList<>();
            for (int k = 0; k < count; k++) {
                int ci = contactAt[k];
                if (a[ci] == body || b[ci] == body) {
                    seen.add(ci);
                }
            }
            for (int i = 1; i < seen.size(); i++) {
                int p = seen.get(i - 1);
                int q = seen.get(i);
                assertTrue(colours[p] < colours[q] || colours[p] == colours[q] && p < q,
                    "body " + body + ": contact " + p + " then " + q);
            }
        }
        // The split: runs of whole islands, from the small islands' start to the end, sharing no moving body.
        // Sharing pays only with minPart contacts a run: asked for more than there are, no runs.
        assertEquals(0, islands.split(threads, count + 1));
        int parts = islands.split(threads, 1);
        if (threads < 2 || islands.islands < 2) {
            // One run shares nothing: the small islands run on one thread.
            assertEquals(0, parts);
            return;
        }
        assertTrue(parts >= 2 && parts <= threads);
        assertEquals(islands.smallStart, islands.runStart(0));
        assertEquals(count, islands.runStart(parts));
        int[] runOf = new int[bodies];
        java.util.Arrays.fill(runOf, -1);
        for (int r = 0; r < parts; r++) {
            assertTrue(islands.runStart(r) <= islands.runStart(r + 1));
            for (int k = islands.runStart(r); k < islands.runStart(r + 1); k++) {
                int ci = contactAt[k];
                for (int body : new int[] {a[ci], b[ci]}) {
                    if (moves(body)) {
                        assertTrue(runOf[body] == -1 || runOf[body] == r, "body " + body + " in two runs");
                        runOf[body] = r;
                    }
                }
            }
        }
        // No moving body of the small islands is touched by a large island's contact.
        for (int k = 0; k < islands.smallStart; k++) {
            int ci = contactAt[k];
            for (int body : new int[] {a[ci], b[ci]}) {
                assertTrue(!moves(body) || runOf[body] == -1, "body " + body + " in a large and a small island");
            }
        }
    }

    private static boolean moves(int body) {
        return body % 7 != 0;
    }

    @net.jqwik.api.Provide
    net.jqwik.api.Arbitrary<Long> seeds() {
        return net.jqwik.api.Arbitraries.longs();
    }
}
