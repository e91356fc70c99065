package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The hot passes visit the slots of the listed bodies in slot order: exactly the slots the scan of
 * every slot would have kept, checked against that scan on random slot tables (static slot 0
 * included, runs across word boundaries, empty lists, tables grown and shrunk between ticks).
 */
class HotContactsTest {
    @Test
    void selectsWhatAScanOfEverySlotWouldKeep() {
        Random random = new Random(7);
        HotContacts hot = new HotContacts();
        for (int round = 0; round < 300; round++) {
            int bodies = 1 + random.nextInt(round % 3 == 0 ? 8 : 300);
            int count = random.nextInt(round % 5 == 0 ? 3 : 700);
            int[] n = new int[count * ContactSolver.CI];
            for (int k = 0; k < count; k++) {
                n[k * ContactSolver.CI + ContactSolver.BODY_A] = random.nextInt(bodies);
                n[k * ContactSolver.CI + ContactSolver.BODY_B] = random.nextInt(4) == 0 ? 0 : random.nextInt(bodies);
            }
            hot.slotsChanged();
            // A few passes in one tick: the index is built once and reused.
            for (int pass = 0; pass < 3; pass++) {
                int workers = 1 + random.nextInt(3);
                hot.clearLists(workers, bodies);
                boolean[] marked = new boolean[bodies];
                for (int b = 1; b < bodies; b++) {
                    if (random.nextInt(pass == 2 ? 2 : 10) == 0) {
                        marked[b] = true;
                        hot.list(random.nextInt(workers), b);
                    }
                }
                hot.select(n, count, bodies);
                List<Integer> expected = new ArrayList<>();
                for (int k = 0; k < count; k++) {
                    if (marked[n[k * ContactSolver.CI + ContactSolver.BODY_A]] || marked[n[k * ContactSolver.CI + ContactSolver.BODY_B]]) {
                        expected.add(k);
                    }
                }
                List<Integer> visited = new ArrayList<>();
                int k = hot.next(0, count);
                while (k < count) {
                    int end = hot.runEnd(k, count);
                    assertTrue(end > k && visited.size() + end - k <= count, "runs must advance: " + k + " to " + end);
                    for (int s = k; s < end; s++) {
                        visited.add(s);
                    }
                    k = hot.next(end, count);
                }
                assertEquals(expected, visited, "round " + round + ", pass " + pass + ": " + bodies + " bodies, " + count + " slots");
            }
        }
    }
}
