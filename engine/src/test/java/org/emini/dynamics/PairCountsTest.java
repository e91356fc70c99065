package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The pair table agrees with a map through growth and removals (backward shifts included). */
class PairCountsTest {
    @Test
    void agreesWithAMapThroughAddsAndRemoves() {
        PairCounts table = new PairCounts();
        Map<Long, Integer> expected = new HashMap<>();
        List<Long> live = new ArrayList<>();
        Random random = new Random(14);
        for (int step = 0; step < 200_000; step++) {
            if (live.isEmpty() || random.nextInt(3) > 0) {
                // Few slots, so that keys repeat (multi-part pairs) and probe runs are long.
                int a = random.nextInt(300);
                int b = random.nextInt(300);
                long key = random.nextBoolean() ? PairCounts.segment(a, b) : a == b ? PairCounts.segment(a, a) : PairCounts.parts(a, b);
                table.add(key);
                if (expected.merge(key, 1, Integer::sum) == 1) {
                    live.add(key);
                }
            } else {
                int i = random.nextInt(live.size());
                long key = live.get(i);
                table.remove(key);
                if (expected.merge(key, -1, Integer::sum) == 0) {
                    expected.remove(key);
                    live.set(i, live.get(live.size() - 1));
                    live.remove(live.size() - 1);
                    assertFalse(table.contains(key));
                }
            }
            if (step % 10_000 == 0) {
                for (long key : live) {
                    assertTrue(table.contains(key));
                }
            }
        }
        for (long key : live) {
            for (int k = expected.get(key); k > 0; k--) {
                assertTrue(table.contains(key));
                table.remove(key);
            }
            assertFalse(table.contains(key));
        }
        assertEquals(0, expected.values().stream().filter(v -> v < 0).count());
    }

    @Test
    void bodyAndSegmentKeysAreApartAndOrderFree() {
        assertEquals(PairCounts.parts(3, 7), PairCounts.parts(7, 3));
        assertTrue(PairCounts.parts(3, 7) != PairCounts.segment(3, 7));
        assertTrue(PairCounts.parts(0, 1) != 0L && PairCounts.segment(0, 0) != 0L);
    }
}
