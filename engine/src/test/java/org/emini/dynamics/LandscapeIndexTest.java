package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import java.util.TreeSet;
import org.emini.collision.Segment;
import org.junit.jupiter.api.Test;

/**
 * The landscape's index and chain joins, kept up to date edit by edit, always agree with a
 * landscape built from scratch with the same segments.
 */
class LandscapeIndexTest {
    private static TreeSet<Integer> query(Landscape l, float x0, float y0, float x1, float y1) {
        TreeSet<Integer> found = new TreeSet<>();
        l.query(x0, y0, x1, y1, slot -> {
            found.add(l.indexOfSlot(slot));
            return true;
        });
        return found;
    }

    /** The slot of each index, found through a query around the segment. */
    private static int slotOf(Landscape l, int index) {
        int[] slot = {-1};
        float x = l.getStartX(index);
        float y = l.getStartY(index);
        l.query(x, y, x, y, s -> {
            if (l.indexOfSlot(s) == index) {
                slot[0] = s;
            }
            return true;
        });
        return slot[0];
    }

    @Test
    void editsOneByOneMatchAFreshBuild() {
        Random r = new Random(12);
        Landscape l = new Landscape();
        Segment a = new Segment();
        Segment b = new Segment();
        for (int step = 0; step < 1500; step++) {
            int op = r.nextInt(10);
            if (op < 6 || l.getSegmentCount() < 5) {
                // Coarse grid points, so that segments often share end points.
                float x = r.nextInt(20) * 10f;
                float y = r.nextInt(20) * 10f;
                l.addSegment(x, y, x + (r.nextInt(3) - 1) * 10f, y + (r.nextInt(3) - 1) * 10f, r.nextInt(3));
            } else {
                l.removeSegment(r.nextInt(l.getSegmentCount()));
            }
            if (r.nextInt(4) == 0) {
                l.prepare();
            }
            if (step % 50 != 49) {
                continue;
            }
            l.prepare();
            Landscape fresh = new Landscape(l);
            fresh.prepare();
            for (int q = 0; q < 20; q++) {
                float x = r.nextInt(22) * 10f - 15f;
                float y = r.nextInt(22) * 10f - 15f;
                float w = r.nextInt(6) * 10f;
                assertEquals(query(fresh, x, y, x + w, y + w), query(l, x, y, x + w, y + w), "step " + step);
            }
            for (int i = 0; i < l.getSegmentCount(); i++) {
                l.fill(slotOf(l, i), a);
                fresh.fill(slotOf(fresh, i), b);
                String where = "step " + step + " segment " + i;
                assertEquals(b.hasPrev, a.hasPrev, where);
                assertEquals(b.hasNext, a.hasNext, where);
                if (a.hasPrev) {
                    assertEquals(b.prevX, a.prevX, where);
                    assertEquals(b.prevY, a.prevY, where);
                }
                if (a.hasNext) {
                    assertEquals(b.nextX, a.nextX, where);
                    assertEquals(b.nextY, a.nextY, where);
                }
            }
        }
    }
}
