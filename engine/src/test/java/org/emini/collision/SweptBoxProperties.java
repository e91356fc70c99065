package org.emini.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.TreeSet;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;

/**
 * {@link SweptBox} against the exact swept-box test in double precision, and the trees' swept
 * queries ({@link BroadPhase#querySwept}, {@link StaticAabbTree#querySwept}) against testing every
 * box: a sweep never misses a box it meets (it may take in a box a few roundings away), and the
 * trees' pruning never drops a box the sweep meets.
 */
class SweptBoxProperties {

    /** Whether [q + t·d] meets b for some t in [0, 1], exactly (slab test in double). */
    static boolean exact(double[] q, double dx, double dy, double[] b) {
        double lo = 0;
        double hi = 1;
        double[] d = {dx, dy};
        for (int a = 0; a < 2; a++) {
            if (d[a] == 0) {
                if (q[a] > b[a + 2] || b[a] > q[a + 2]) {
                    return false;
                }
                continue;
            }
            double enter = (b[a] - q[a + 2]) / d[a];
            double leave = (b[a + 2] - q[a]) / d[a];
            lo = Math.max(lo, Math.min(enter, leave));
            hi = Math.min(hi, Math.max(enter, leave));
        }
        return lo <= hi;
    }

    private static float coarse(Random r, float scale) {
        // Coarse values make touching boxes and axis-parallel sweeps common.
        return r.nextBoolean() ? r.nextInt(20) * scale / 20f : r.nextFloat() * scale;
    }

    @Property(tries = 200, seed = "23")
    void aSweepNeverMissesABoxItMeets(@ForAll long seed) {
        Random r = new Random(seed);
        SweptBox sweep = new SweptBox();
        for (int k = 0; k < 200; k++) {
            float x = coarse(r, 400f) - 200f;
            float y = coarse(r, 400f) - 200f;
            float[] q = {x, y, x + coarse(r, 30f), y + coarse(r, 30f)};
            float dx = r.nextInt(4) == 0 ? 0f : coarse(r, 400f) - 200f;
            float dy = r.nextInt(4) == 0 ? 0f : coarse(r, 400f) - 200f;
            float bx = coarse(r, 400f) - 200f;
            float by = coarse(r, 400f) - 200f;
            float[] b = {bx, by, bx + coarse(r, 50f), by + coarse(r, 50f)};
            sweep.set(q[0], q[1], q[2], q[3], dx, dy);
            boolean meets = sweep.meets(b[0], b[1], b[2], b[3]);
            double[] qd = {q[0], q[1], q[2], q[3]};
            double[] bd = {b[0], b[1], b[2], b[3]};
            if (exact(qd, dx, dy, bd)) {
                assertTrue(meets, sweep + " misses box " + java.util.Arrays.toString(b));
            } else if (meets) {
                // Only within the rounding allowance.
                double pad = 1e-5 * 1000;
                double[] grown = {bd[0] - pad, bd[1] - pad, bd[2] + pad, bd[3] + pad};
                assertTrue(exact(qd, dx, dy, grown), sweep + " takes in far box " + java.util.Arrays.toString(b));
            }
        }
    }

    @Property(tries = 60, seed = "24")
    void treesReportExactlyTheBoxesTheSweepMeets(@ForAll @IntRange(min = 0, max = 400) int n, @ForAll long seed) {
        Random r = new Random(seed);
        BroadPhase bp = new BroadPhase(r.nextFloat() * 3f);
        float[] minX = new float[n];
        float[] minY = new float[n];
        float[] maxX = new float[n];
        float[] maxY = new float[n];
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            minX[i] = r.nextFloat() * 1000f;
            minY[i] = r.nextFloat() * 1000f;
            maxX[i] = minX[i] + r.nextFloat() * 30f;
            maxY[i] = minY[i] + r.nextFloat() * 30f;
            ids[i] = i;
            bp.createProxy(minX[i], minY[i], maxX[i], maxY[i], i, r.nextInt(3) == 0);
        }
        StaticAabbTree tree = new StaticAabbTree();
        tree.build(n, minX, minY, maxX, maxY, ids);
        SweptBox sweep = new SweptBox();
        for (int q = 0; q < 20; q++) {
            float x = r.nextFloat() * 1000f;
            float y = r.nextFloat() * 1000f;
            float size = q % 2 == 0 ? 0f : r.nextFloat() * 40f;
            sweep.set(x, y, x + size, y + size, r.nextFloat() * 1200f - 600f, r.nextFloat() * 1200f - 600f);
            TreeSet<Integer> expectedFat = new TreeSet<>();
            TreeSet<Integer> expected = new TreeSet<>();
            for (int i = 0; i < n; i++) {
                if (sweep.meets(bp.getFatMinX(i), bp.getFatMinY(i), bp.getFatMaxX(i), bp.getFatMaxY(i))) {
                    expectedFat.add(i);
                }
                if (sweep.meets(minX[i], minY[i], maxX[i], maxY[i])) {
                    expected.add(i);
                }
            }
            TreeSet<Integer> found = new TreeSet<>();
            bp.querySwept(sweep, id -> found.add(id) || true);
            assertEquals(expectedFat, found, sweep + " in the broadphase");
            TreeSet<Integer> inTree = new TreeSet<>();
            tree.querySwept(sweep, id -> inTree.add(id) || true);
            assertEquals(expected, inTree, sweep + " in the static tree");
        }
    }
}
