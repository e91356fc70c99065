package org.emini.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.TreeSet;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;

/** The static tree finds exactly what a brute-force scan finds, and stays balanced. */
class StaticAabbTreeProperties {
    private static final class Collect implements QueryCallback {
        final List<Integer> ids = new ArrayList<>();

        @Override
        public boolean reportProxy(int id) {
            ids.add(id);
            return true;
        }
    }

    @Property(tries = 200)
    void queriesMatchBruteForce(@ForAll @IntRange(min = 0, max = 700) int n, @ForAll long seed) {
        Random r = new Random(seed);
        float[] minX = new float[n];
        float[] minY = new float[n];
        float[] maxX = new float[n];
        float[] maxY = new float[n];
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            // Coarse coordinates make ties, duplicates and zero-size boxes common.
            minX[i] = r.nextInt(40) * 5f;
            minY[i] = r.nextInt(40) * 5f;
            maxX[i] = minX[i] + r.nextInt(4) * 5f;
            maxY[i] = minY[i] + r.nextInt(4) * 5f;
            ids[i] = 1000 + i;
        }
        StaticAabbTree tree = new StaticAabbTree();
        tree.build(n, minX, minY, maxX, maxY, ids);
        assertEquals(n, tree.getItemCount());
        int leaves = (n + StaticAabbTree.LEAF_SIZE - 1) / StaticAabbTree.LEAF_SIZE;
        int bound = n == 0 ? 0 : 2 + (int) Math.ceil(Math.log(Math.max(leaves, 1)) / Math.log(2));
        assertTrue(tree.getHeight() <= bound, "height " + tree.getHeight() + " for " + n + " items");
        for (int q = 0; q < 20; q++) {
            float qx = r.nextInt(45) * 5f - 10f;
            float qy = r.nextInt(45) * 5f - 10f;
            float qw = r.nextInt(12) * 5f;
            float qh = r.nextInt(12) * 5f;
            TreeSet<Integer> expected = new TreeSet<>();
            for (int i = 0; i < n; i++) {
                if (minX[i] <= qx + qw && qx <= maxX[i] && minY[i] <= qy + qh && qy <= maxY[i]) {
                    expected.add(ids[i]);
                }
            }
            Collect c = new Collect();
            tree.query(qx, qy, qx + qw, qy + qh, c);
            assertEquals(expected.size(), c.ids.size(), "each item reported once");
            assertEquals(expected, new TreeSet<>(c.ids));
        }
    }

    @Test
    void buildIsDeterministicAndQueriesStopWhenAsked() {
        Random r = new Random(3);
        int n = 500;
        float[] x = new float[n];
        float[] y = new float[n];
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            x[i] = r.nextFloat() * 100f;
            y[i] = r.nextFloat() * 100f;
            ids[i] = i;
        }
        StaticAabbTree a = new StaticAabbTree();
        StaticAabbTree b = new StaticAabbTree();
        a.build(n, x, y, x, y, ids);
        b.build(n, x, y, x, y, ids);
        Collect ca = new Collect();
        Collect cb = new Collect();
        a.query(0f, 0f, 100f, 100f, ca);
        b.query(0f, 0f, 100f, 100f, cb);
        assertEquals(ca.ids, cb.ids);
        int[] count = {0};
        a.query(0f, 0f, 100f, 100f, id -> ++count[0] < 3);
        assertEquals(3, count[0]);
        // Rebuilding smaller reuses the arrays and forgets the old items.
        a.build(1, x, y, x, y, ids);
        Collect one = new Collect();
        a.query(0f, 0f, 100f, 100f, one);
        assertEquals(List.of(0), one.ids);
    }
}
