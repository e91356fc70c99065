package org.emini.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.lang.management.ManagementFactory;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

class BroadPhaseTest {

    /** Records pairs as "userDataA-userDataB" strings, in the order reported. */
    static final class Recorder implements PairCallback {
        final List<String> pairs = new ArrayList<>();

        @Override
        public void addPair(int userDataA, int userDataB) {
            pairs.add(userDataA + "-" + userDataB);
        }

        List<String> take() {
            List<String> out = new ArrayList<>(pairs);
            pairs.clear();
            return out;
        }
    }

    /** Collects the proxies reported by a query. */
    static final class Collector implements QueryCallback {
        final TreeSet<Integer> found = new TreeSet<>();

        @Override
        public boolean reportProxy(int proxyId) {
            found.add(proxyId);
            return true;
        }
    }

    static List<String> update(BroadPhase bp) {
        Recorder r = new Recorder();
        bp.updatePairs(r);
        bp.validate();
        return r.take();
    }

    static double log2(int n) {
        return Math.log(n) / Math.log(2);
    }

    // ---------------------------------------------------------------------------------------------
    // Construction and ids

    @Test
    void rejectsBadMargin() {
        for (float m : new float[] {Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, -1f}) {
            IllegalArgumentException e =
                    assertThrows(IllegalArgumentException.class, () -> new BroadPhase(m));
            assertTrue(e.getMessage().contains("BroadPhase"), e.getMessage());
        }
        assertEquals(0f, new BroadPhase(0f).getMargin());
    }

    @Test
    void aNewMarginRefattensEveryBoxAndReportsThePairsItBrings() {
        BroadPhase bp = new BroadPhase(2f);
        // 100 boxes of 10 px in a row, 20 px apart: margins of 2 keep them apart, 6 make neighbours pairs.
        for (int i = 0; i < 100; i++) {
            bp.createProxy(20f * i, 0f, 20f * i + 10f, 10f, i, i % 2 == 0);
        }
        assertTrue(update(bp).isEmpty());
        bp.setMargin(6f);
        assertEquals(6f, bp.getMargin());
        assertEquals(100, bp.getMoveCount());
        for (int i = 0; i < 100; i++) {
            assertEquals(20f * i - 6f, bp.getFatMinX(i));
            assertEquals(16f, bp.getFatMaxY(i));
        }
        assertEquals(99, update(bp).size());
        bp.setMargin(0f);
        assertEquals(20f * 7, bp.getFatMinX(7));
        assertTrue(update(bp).isEmpty());
        assertThrows(IllegalArgumentException.class, () -> bp.setMargin(Float.NaN));
        assertThrows(IllegalArgumentException.class, () -> bp.setMargin(-1f));
    }

    @Test
    void emptyBroadPhase() {
        BroadPhase bp = new BroadPhase(2f);
        bp.validate();
        assertEquals(0, bp.getProxyCount());
        assertEquals(0, bp.getTreeHeight());
        assertEquals(0, bp.getMoveCount());
        assertEquals(List.of(), update(bp));
        Collector c = new Collector();
        bp.query(-1e6f, -1e6f, 1e6f, 1e6f, c);
        assertTrue(c.found.isEmpty());
    }

    @Test
    void idsAreDenseAndFreedIdsAreReusedLastFreedFirst() {
        BroadPhase bp = new BroadPhase(1f);
        for (int i = 0; i < 5; i++) {
            assertEquals(i, bp.createProxy(i * 100, 0, i * 100 + 10, 10, i));
        }
        bp.destroyProxy(1);
        bp.destroyProxy(3);
        bp.validate();
        assertEquals(3, bp.getProxyCount());
        assertEquals(3, bp.createProxy(0, 0, 1, 1, 33));
        assertEquals(1, bp.createProxy(0, 0, 1, 1, 11));
        assertEquals(5, bp.createProxy(0, 0, 1, 1, 55));
        assertEquals(33, bp.getUserData(3));
        assertEquals(11, bp.getUserData(1));
        bp.validate();
    }

    @Test
    void fatAabbIsTightPlusMargin() {
        BroadPhase bp = new BroadPhase(2f);
        int p = bp.createProxy(10, 20, 30, 50, 7);
        assertEquals(8f, bp.getFatMinX(p));
        assertEquals(18f, bp.getFatMinY(p));
        assertEquals(32f, bp.getFatMaxX(p));
        assertEquals(52f, bp.getFatMaxY(p));
        assertEquals(7, bp.getUserData(p));
        assertEquals(1, bp.getMoveCount());
        assertTrue(bp.isMoved(p));
    }

    // ---------------------------------------------------------------------------------------------
    // Moving

    @Test
    void moveInsideFatAabbDoesNothing() {
        BroadPhase bp = new BroadPhase(2f);
        int p = bp.createProxy(10, 20, 30, 50, 7);
        update(bp);
        assertFalse(bp.moveProxy(p, 11.5f, 18f, 31.9f, 51f, 0.05f, 0.5f));
        assertEquals(0, bp.getMoveCount());
        assertFalse(bp.isMoved(p));
        assertEquals(8f, bp.getFatMinX(p));
        assertEquals(52f, bp.getFatMaxY(p));
    }

    /** A box still inside its fat box but about to leave it (set moving fast) is re-inserted, so its pairs ahead are found. */
    @Test
    void moveInsideWhoseSweepLeavesTheFatAabbReinserts() {
        BroadPhase bp = new BroadPhase(2f);
        int p = bp.createProxy(10, 20, 30, 50, 7);
        int ahead = bp.createProxy(100, 20, 102, 50, 8);
        update(bp);
        assertTrue(bp.moveProxy(p, 10, 20, 30, 50, 160f, 0f));
        assertTrue(bp.getFatMaxX(p) >= 30f + 160f);
        assertTrue(bp.testOverlap(p, ahead));
        bp.validate();
    }

    @Test
    void moveOutsideReinsertsStretchedAlongTheDisplacement() {
        BroadPhase bp = new BroadPhase(2f);
        int p = bp.createProxy(10, 20, 30, 50, 7);
        update(bp);
        assertTrue(bp.moveProxy(p, 13, 18, 33, 48, 3, -2));
        assertEquals(1, bp.getMoveCount());
        assertTrue(bp.isMoved(p));
        assertEquals(11f, bp.getFatMinX(p));
        assertEquals(18f - 2f - 8f, bp.getFatMinY(p));
        assertEquals(33f + 2f + 12f, bp.getFatMaxX(p));
        assertEquals(50f, bp.getFatMaxY(p));
        bp.validate();
    }

    @Test
    void oversizedFatAabbIsShrunkOnceTheShapeSlowsDown() {
        BroadPhase bp = new BroadPhase(2f);
        int p = bp.createProxy(0, 0, 10, 10, 0);
        assertTrue(bp.moveProxy(p, 20, 0, 30, 10, 50, 0));
        assertEquals(30f + 2f + 200f, bp.getFatMaxX(p));
        update(bp);
        // Still inside, still moving fast: kept.
        assertFalse(bp.moveProxy(p, 25, 0, 35, 10, 50, 0));
        // Stopped: the box reaches far beyond what a resting shape needs, so it is rebuilt.
        assertTrue(bp.moveProxy(p, 25, 0, 35, 10, 0, 0));
        assertEquals(23f, bp.getFatMinX(p));
        assertEquals(37f, bp.getFatMaxX(p));
        // And then it rests.
        update(bp);
        assertFalse(bp.moveProxy(p, 25, 0, 35, 10, 0, 0));
        bp.validate();
    }

    @Test
    void steadyMotionReinsertsOnlyWhenLeavingTheFatAabb() {
        BroadPhase bp = new BroadPhase(2f);
        int p = bp.createProxy(0, 0, 10, 10, 0);
        int reinserts = 0;
        for (int step = 1; step <= 100; step++) {
            float x = step * 10f;
            boolean inside = bp.getFatMinX(p) <= x && x + 10f + 10f <= bp.getFatMaxX(p);
            boolean moved = bp.moveProxy(p, x, 0, x + 10f, 10, 10f, 0);
            assertEquals(!inside, moved, "step " + step);
            if (moved) {
                reinserts++;
            }
        }
        // The box is stretched by four steps ahead, so roughly one step in four re-inserts.
        assertTrue(reinserts <= 25, "reinserts " + reinserts);
    }

    @Test
    void restingShapeNeverTouchesTheTree() {
        BroadPhase bp = new BroadPhase(0f);
        int p = bp.createProxy(0, 0, 10, 10, 0);
        update(bp);
        for (int i = 0; i < 10; i++) {
            assertFalse(bp.moveProxy(p, 0, 0, 10, 10, 0, 0));
        }
        assertEquals(0, bp.getMoveCount());
    }

    // ---------------------------------------------------------------------------------------------
    // Pairs

    @Test
    void overlappingPairIsReportedOnceWithSmallerIdFirst() {
        BroadPhase bp = new BroadPhase(1f);
        int a = bp.createProxy(0, 0, 10, 10, 100);
        int b = bp.createProxy(5, 5, 15, 15, 200);
        assertEquals(0, a);
        assertEquals(1, b);
        assertTrue(bp.testOverlap(a, b));
        assertEquals(List.of("100-200"), update(bp));
        assertEquals(0, bp.getMoveCount());
        assertEquals(List.of(), update(bp));
        // Both moved: still once.
        assertTrue(bp.moveProxy(a, 30, 30, 40, 40, 0, 0));
        assertTrue(bp.moveProxy(b, 35, 35, 45, 45, 0, 0));
        assertEquals(List.of("100-200"), update(bp));
        // Only the larger id moved: smaller id's user data still first.
        assertTrue(bp.moveProxy(b, 32, 32, 42, 42, 0, 0));
        assertEquals(List.of("100-200"), update(bp));
    }

    @Test
    void separatedProxiesAreNotReported() {
        BroadPhase bp = new BroadPhase(1f);
        int a = bp.createProxy(0, 0, 10, 10, 1);
        int b = bp.createProxy(12.5f, 0, 20, 10, 2);
        assertFalse(bp.testOverlap(a, b));
        assertEquals(List.of(), update(bp));
    }

    @Test
    void touchingFatAabbsOverlap() {
        BroadPhase bp = new BroadPhase(0f);
        int a = bp.createProxy(0, 0, 10, 10, 1);
        int b = bp.createProxy(10, 10, 20, 20, 2);
        assertTrue(bp.testOverlap(a, b));
        assertEquals(List.of("1-2"), update(bp));
    }

    @Test
    void touchProxyReportsItsPairsAgain() {
        BroadPhase bp = new BroadPhase(1f);
        int a = bp.createProxy(0, 0, 10, 10, 1);
        bp.createProxy(5, 5, 15, 15, 2);
        bp.createProxy(100, 100, 115, 115, 3);
        update(bp);
        bp.touchProxy(a);
        bp.touchProxy(a);
        assertEquals(1, bp.getMoveCount());
        assertEquals(List.of("1-2"), update(bp));
    }

    @Test
    void destroyedProxyLeavesTheMoveBufferAndIsNotReported() {
        BroadPhase bp = new BroadPhase(1f);
        int a = bp.createProxy(0, 0, 10, 10, 1);
        int b = bp.createProxy(1, 1, 11, 11, 2);
        int c = bp.createProxy(2, 2, 12, 12, 3);
        assertEquals(3, bp.getMoveCount());
        bp.destroyProxy(b);
        assertEquals(2, bp.getMoveCount());
        bp.validate();
        assertEquals(List.of("1-3"), update(bp));
        // Destroying a proxy that did not move leaves others' pairs to them.
        bp.touchProxy(c);
        bp.destroyProxy(a);
        assertEquals(List.of(), update(bp));
    }

    @Test
    void pairsAreSortedByProxyIds() {
        BroadPhase bp = new BroadPhase(1f);
        Random rnd = new Random(3);
        for (int i = 0; i < 30; i++) {
            float x = rnd.nextFloat() * 5f;
            bp.createProxy(x, x, x + 10, x + 10, i * 10);
        }
        List<String> pairs = update(bp);
        assertEquals(30 * 29 / 2, pairs.size());
        List<String> expected = new ArrayList<>();
        for (int i = 0; i < 30; i++) {
            for (int j = i + 1; j < 30; j++) {
                expected.add(i * 10 + "-" + j * 10);
            }
        }
        assertEquals(expected, pairs);
    }

    @Test
    void knownPairsAreLeftOutAndDoNotCountTowardsTheLimit() {
        BroadPhase bp = new BroadPhase(1f);
        for (int i = 0; i < 6; i++) {
            bp.createProxy(i, 0, i + 10, 10, i);
        }
        // Pairs with proxy 0 or 1 are known; the other six of the fifteen are new.
        List<String> asked = new ArrayList<>();
        List<String> reported = new ArrayList<>();
        PairCallback r = new PairCallback() {
            @Override
            public void addPair(int userDataA, int userDataB) {
                reported.add(userDataA + "-" + userDataB);
            }

            @Override
            public boolean isKnownPair(int userDataA, int userDataB) {
                assertTrue(reported.isEmpty(), "asked after a pair was reported");
                asked.add(Math.min(userDataA, userDataB) + "-" + Math.max(userDataA, userDataB));
                return Math.min(userDataA, userDataB) < 2;
            }
        };
        bp.setPairLimit(6);
        bp.updatePairs(r);
        bp.validate();
        assertFalse(bp.isPairLimitReached());
        assertEquals(List.of("2-3", "2-4", "2-5", "3-4", "3-5", "4-5"), reported);
        assertEquals(15, new TreeSet<>(asked).size());
        assertEquals(15, asked.size());
        // One pair fewer allowed: the limit counts the new pairs only, and stops at them.
        for (int i = 0; i < 6; i++) {
            bp.touchProxy(i);
        }
        reported.clear();
        bp.setPairLimit(5);
        bp.updatePairs(r);
        assertTrue(bp.isPairLimitReached());
        assertEquals(5, reported.size());
    }

    // ---------------------------------------------------------------------------------------------
    // Queries and callbacks

    @Test
    void queryFindsExactlyTheOverlappingProxiesAndStopsWhenAsked() {
        BroadPhase bp = new BroadPhase(0f);
        for (int i = 0; i < 100; i++) {
            bp.createProxy(i * 10, 0, i * 10 + 5, 5, i);
        }
        Collector c = new Collector();
        bp.query(12, 1, 40, 2, c);
        assertEquals(new TreeSet<>(List.of(1, 2, 3, 4)), c.found);
        int[] calls = {0};
        bp.query(-1000, -1000, 1000, 1000, id -> ++calls[0] < 3);
        assertEquals(3, calls[0]);
        bp.validate();
    }

    @Test
    void callbacksMayReadAndQueryButNotModify() {
        BroadPhase bp = new BroadPhase(1f);
        int a = bp.createProxy(0, 0, 10, 10, 0);
        int b = bp.createProxy(5, 5, 15, 15, 1);
        int[] nested = {0};
        bp.updatePairs((ua, ub) -> {
            assertTrue(bp.testOverlap(a, b));
            assertEquals(1, bp.getUserData(b));
            bp.query(0, 0, 1, 1, id -> {
                nested[0]++;
                bp.query(0, 0, 1, 1, id2 -> {
                    nested[0]++;
                    return true;
                });
                return true;
            });
            assertThrows(IllegalStateException.class, () -> bp.createProxy(0, 0, 1, 1, 0));
            assertThrows(IllegalStateException.class, () -> bp.touchProxy(a));
            assertThrows(IllegalStateException.class, () -> bp.updatePairs((x, y) -> { }));
        });
        assertEquals(2, nested[0]);
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> bp.query(0, 0, 20, 20, id -> {
                    bp.destroyProxy(id);
                    return true;
                }));
        assertTrue(e.getMessage().contains("destroyProxy"), e.getMessage());
        assertThrows(IllegalStateException.class,
                () -> bp.query(0, 0, 20, 20, id -> {
                    bp.moveProxy(id, 0, 0, 1, 1, 0, 0);
                    return true;
                }));
        // The lock is released after a callback throws.
        assertTrue(bp.moveProxy(a, 100, 100, 110, 110, 0, 0));
        assertTrue(bp.moveProxy(a, 3, 3, 9, 9, 0, 0));
        bp.validate();
        RuntimeException boom = new RuntimeException("boom");
        assertThrows(RuntimeException.class, () -> bp.updatePairs((x, y) -> {
            throw boom;
        }));
        assertEquals(0, bp.getMoveCount());
        bp.destroyProxy(b);
        bp.validate();
    }

    // ---------------------------------------------------------------------------------------------
    // Bad input

    private static void assertRejected(String method, Executable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call);
        assertTrue(e.getMessage().startsWith(method + ":"), e.getMessage());
    }

    @Test
    void badInputIsRejectedNamingTheMethod() {
        BroadPhase bp = new BroadPhase(1f);
        int p = bp.createProxy(0, 0, 1, 1, 0);
        int dead = bp.createProxy(0, 0, 1, 1, 1);
        bp.destroyProxy(dead);
        float nan = Float.NaN;
        float inf = Float.POSITIVE_INFINITY;

        assertRejected("createProxy", () -> bp.createProxy(nan, 0, 1, 1, 0));
        assertRejected("createProxy", () -> bp.createProxy(0, -inf, 1, 1, 0));
        assertRejected("createProxy", () -> bp.createProxy(0, 0, inf, 1, 0));
        assertRejected("createProxy", () -> bp.createProxy(0, 0, 1, nan, 0));
        assertRejected("createProxy", () -> bp.createProxy(2, 0, 1, 1, 0));
        assertRejected("createProxy", () -> bp.createProxy(0, 2, 1, 1, 0));

        for (int bad : new int[] {-1, dead, 2, 1000, Integer.MIN_VALUE}) {
            assertRejected("destroyProxy", () -> bp.destroyProxy(bad));
            assertRejected("moveProxy", () -> bp.moveProxy(bad, 0, 0, 1, 1, 0, 0));
            assertRejected("touchProxy", () -> bp.touchProxy(bad));
            assertRejected("testOverlap", () -> bp.testOverlap(p, bad));
            assertRejected("testOverlap", () -> bp.testOverlap(bad, p));
            assertRejected("getUserData", () -> bp.getUserData(bad));
            assertRejected("getFatMinX", () -> bp.getFatMinX(bad));
            assertRejected("getFatMinY", () -> bp.getFatMinY(bad));
            assertRejected("getFatMaxX", () -> bp.getFatMaxX(bad));
            assertRejected("getFatMaxY", () -> bp.getFatMaxY(bad));
            assertRejected("isMoved", () -> bp.isMoved(bad));
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> bp.getUserData(dead));
        assertTrue(e.getMessage().contains(Integer.toString(dead)), e.getMessage());

        assertRejected("moveProxy", () -> bp.moveProxy(p, nan, 0, 1, 1, 0, 0));
        assertRejected("moveProxy", () -> bp.moveProxy(p, 0, 0, 1, 1, inf, 0));
        assertRejected("moveProxy", () -> bp.moveProxy(p, 0, 0, 1, 1, 0, nan));
        assertRejected("moveProxy", () -> bp.moveProxy(p, 0, 0, -1, 1, 0, 0));
        e = assertThrows(IllegalArgumentException.class,
                () -> bp.moveProxy(p, 0, 0, 1, nan, 0, 0));
        assertTrue(e.getMessage().contains("NaN"), e.getMessage());

        assertRejected("query", () -> bp.query(0, 0, nan, 1, id -> true));
        assertRejected("query", () -> bp.query(0, 0, 1, -1, id -> true));
        assertRejected("query", () -> bp.query(0, 0, 1, 1, null));
        assertRejected("updatePairs", () -> bp.updatePairs(null));
        assertRejected("shiftOrigin", () -> bp.shiftOrigin(nan, 0));
        assertRejected("shiftOrigin", () -> bp.shiftOrigin(0, -inf));

        // Nothing was changed by the rejected calls.
        bp.validate();
        assertEquals(1, bp.getProxyCount());
        assertEquals(0f, bp.getFatMaxX(p) - 2f);
    }

    // ---------------------------------------------------------------------------------------------
    // Origin shift

    @Test
    void shiftOriginTranslatesEveryBoxAndKeepsPairs() {
        BroadPhase bp = new BroadPhase(2f);
        Random rnd = new Random(11);
        for (int i = 0; i < 200; i++) {
            float x = 1e5f + rnd.nextFloat() * 500f;
            float y = 1e5f + rnd.nextFloat() * 500f;
            bp.createProxy(x, y, x + 20, y + 20, i);
        }
        float[] minX = new float[200];
        for (int i = 0; i < 200; i++) {
            minX[i] = bp.getFatMinX(i);
        }
        List<String> before = update(bp);
        bp.shiftOrigin(1e5f, 1e5f);
        bp.validate();
        for (int i = 0; i < 200; i++) {
            assertEquals(minX[i] - 1e5f, bp.getFatMinX(i));
            bp.touchProxy(i);
        }
        assertEquals(before, update(bp));
        Collector c = new Collector();
        bp.query(-10, -10, 600, 600, c);
        assertEquals(200, c.found.size());
    }

    // ---------------------------------------------------------------------------------------------
    // Balance

    private static void assertBalanced(BroadPhase bp) {
        int n = bp.getProxyCount();
        double bound = 2.5 * log2(n) + 4;
        assertTrue(bp.getTreeHeight() <= bound,
                "height " + bp.getTreeHeight() + " for " + n + " proxies, bound " + bound);
    }

    @Test
    void sortedInsertionAlongALineStaysBalanced() {
        for (int order = 0; order < 3; order++) {
            BroadPhase bp = new BroadPhase(2f);
            for (int i = 0; i < 1000; i++) {
                int k = order == 1 ? 999 - i : i;
                float y = order == 2 ? k * 10f : 0f;
                bp.createProxy(k * 10f, y, k * 10f + 8f, y + 8f, k);
            }
            bp.validate();
            assertBalanced(bp);
            // Sliding the whole line along keeps it balanced too.
            update(bp);
            for (int i = 0; i < 1000; i++) {
                float y = order == 2 ? i * 10f : 0f;
                bp.moveProxy(i, i * 10f + 50f, y, i * 10f + 58f, y + 8f, 0, 0);
            }
            bp.validate();
            assertBalanced(bp);
            // Destroying every other one, in order.
            for (int i = 0; i < 1000; i += 2) {
                bp.destroyProxy(i);
            }
            bp.validate();
            assertBalanced(bp);
        }
    }

    @Test
    void identicalBoxesStayBalanced() {
        BroadPhase bp = new BroadPhase(1f);
        for (int i = 0; i < 1000; i++) {
            bp.createProxy(0, 0, 1, 1, i);
        }
        bp.validate();
        assertBalanced(bp);
    }

    // ---------------------------------------------------------------------------------------------
    // Stress

    private static long bruteForcePairCount(BroadPhase bp, int n) {
        float[] x0 = new float[n];
        float[] y0 = new float[n];
        float[] x1 = new float[n];
        float[] y1 = new float[n];
        for (int i = 0; i < n; i++) {
            x0[i] = bp.getFatMinX(i);
            y0[i] = bp.getFatMinY(i);
            x1[i] = bp.getFatMaxX(i);
            y1[i] = bp.getFatMaxY(i);
        }
        long count = 0;
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                if (x0[i] <= x1[j] && x0[j] <= x1[i] && y0[i] <= y1[j] && y0[j] <= y1[i]) {
                    count++;
                }
            }
        }
        return count;
    }

    @Test
    void stressTenThousandProxies() {
        int n = 10_000;
        BroadPhase bp = new BroadPhase(2f);
        Random rnd = new Random(42);
        float[] x = new float[n];
        float[] y = new float[n];
        float[] vx = new float[n];
        float[] vy = new float[n];
        for (int i = 0; i < n; i++) {
            x[i] = rnd.nextFloat() * 4000f;
            y[i] = rnd.nextFloat() * 4000f;
            vx[i] = (rnd.nextFloat() - 0.5f) * 6f;
            vy[i] = (rnd.nextFloat() - 0.5f) * 6f;
            assertEquals(i, bp.createProxy(x[i], y[i], x[i] + 20f, y[i] + 20f, i));
        }
        bp.validate();
        assertBalanced(bp);
        long[] count = {0};
        bp.updatePairs((a, b) -> {
            assertTrue(a < b);
            count[0]++;
        });
        assertEquals(bruteForcePairCount(bp, n), count[0]);

        for (int step = 0; step < 20; step++) {
            for (int i = 0; i < n; i++) {
                x[i] += vx[i];
                y[i] += vy[i];
                bp.moveProxy(i, x[i], y[i], x[i] + 20f, y[i] + 20f, vx[i], vy[i]);
            }
            bp.updatePairs((a, b) -> count[0]++);
        }
        bp.validate();
        assertBalanced(bp);
        for (int i = 0; i < n; i += 2) {
            bp.destroyProxy(i);
        }
        bp.validate();
        assertBalanced(bp);
        for (int i = 1; i < n; i += 2) {
            bp.destroyProxy(i);
        }
        bp.validate();
        assertEquals(0, bp.getProxyCount());
        assertEquals(0, bp.getTreeHeight());
    }

    // ---------------------------------------------------------------------------------------------
    // Determinism

    private static List<String> scenario() {
        BroadPhase bp = new BroadPhase(2f);
        Random rnd = new Random(7);
        List<String> log = new ArrayList<>();
        List<Integer> live = new ArrayList<>();
        Recorder r = new Recorder();
        for (int step = 0; step < 300; step++) {
            int op = rnd.nextInt(10);
            if (op < 4 || live.isEmpty()) {
                float px = rnd.nextFloat() * 300f;
                float py = rnd.nextFloat() * 300f;
                int id = bp.createProxy(px, py, px + 15f, py + 15f, step);
                live.add(id);
                log.add("c" + id);
            } else if (op < 7) {
                int id = live.get(rnd.nextInt(live.size()));
                float px = rnd.nextFloat() * 300f;
                float py = rnd.nextFloat() * 300f;
                log.add("m" + bp.moveProxy(id, px, py, px + 15f, py + 15f, 1f, -1f));
            } else if (op < 8) {
                bp.destroyProxy(live.remove(rnd.nextInt(live.size())));
            } else {
                bp.updatePairs(r);
                log.addAll(r.take());
                log.add("h" + bp.getTreeHeight());
            }
        }
        return log;
    }

    @Test
    void sameOperationsGiveIdenticalIdsAndPairs() {
        List<String> first = scenario();
        assertTrue(first.size() > 300);
        assertEquals(first, scenario());
    }

    // ---------------------------------------------------------------------------------------------
    // Validation

    /** The broadphase's dynamic tree (all proxies of smallTree are dynamic). */
    private static DynamicTree dynamicTree(BroadPhase bp) throws ReflectiveOperationException {
        Field f = BroadPhase.class.getDeclaredField("trees");
        f.setAccessible(true);
        return ((DynamicTree[]) f.get(bp))[1];
    }

    private static void corruptTree(BroadPhase bp, String field, int index, Object value)
            throws ReflectiveOperationException {
        Field f = DynamicTree.class.getDeclaredField(field);
        f.setAccessible(true);
        java.lang.reflect.Array.set(f.get(dynamicTree(bp)), index, value);
    }

    private static BroadPhase smallTree() {
        BroadPhase bp = new BroadPhase(1f);
        for (int i = 0; i < 8; i++) {
            bp.createProxy(i * 5, 0, i * 5 + 3, 3, i);
        }
        bp.validate();
        return bp;
    }

    @Test
    void validateReportsBrokenInvariants() throws ReflectiveOperationException {
        BroadPhase bp = smallTree();
        // A leaf's box grows without its ancestors being refitted (node 0's max x: box[4 * 0 + 2]).
        corruptTree(bp, "box", 2, 1000f);
        IllegalStateException e = assertThrows(IllegalStateException.class, bp::validate);
        assertTrue(e.getMessage().contains("union"), e.getMessage());

        bp = smallTree();
        Field rootField = DynamicTree.class.getDeclaredField("root");
        rootField.setAccessible(true);
        int root = (int) rootField.get(dynamicTree(bp));
        // The root's height: link[4 * root + 2].
        corruptTree(bp, "link", 4 * root + 2, 99);
        e = assertThrows(IllegalStateException.class, bp::validate);
        assertTrue(e.getMessage().contains("height"), e.getMessage());

        bp = smallTree();
        corruptTree(bp, "nodeParent", 0, 0);
        assertThrows(IllegalStateException.class, bp::validate);

        bp = smallTree();
        Field movedField = BroadPhase.class.getDeclaredField("moved");
        movedField.setAccessible(true);
        Field moveIndex = MovedPairs.class.getDeclaredField("moveIndex");
        moveIndex.setAccessible(true);
        ((int[]) moveIndex.get(movedField.get(bp)))[3] = 0;
        assertThrows(IllegalStateException.class, bp::validate);
    }

    // ---------------------------------------------------------------------------------------------
    // Allocation

    /** Counts pairs without allocating. */
    static final class Counter implements PairCallback, QueryCallback {
        long sum;

        @Override
        public void addPair(int userDataA, int userDataB) {
            sum += userDataA * 31L + userDataB;
        }

        @Override
        public boolean reportProxy(int proxyId) {
            sum += proxyId;
            return true;
        }
    }

    /** One period of a periodic scene: boxes oscillating, one proxy recreated every step. */
    private static void period(BroadPhase bp, float[] baseX, float[] baseY, int[] ids,
            Counter counter) {
        int n = baseX.length;
        for (int t = 0; t < 40; t++) {
            float phase = t < 20 ? t : 40 - t;
            float v = t < 20 ? 3f : -3f;
            for (int i = 1; i < n; i++) {
                float dir = (i & 1) == 0 ? 1f : -1f;
                float x = baseX[i] + dir * 3f * phase;
                bp.moveProxy(ids[i], x, baseY[i], x + 10f, baseY[i] + 10f, dir * v, 0f);
            }
            bp.destroyProxy(ids[0]);
            ids[0] = bp.createProxy(baseX[0], baseY[0], baseX[0] + 10f, baseY[0] + 10f, 0);
            bp.updatePairs(counter);
            bp.query(0f, 0f, 100f, 100f, counter);
        }
    }

    @Test
    void steadyStateAllocatesNothing() {
        java.lang.management.ThreadMXBean plain = ManagementFactory.getThreadMXBean();
        assumeTrue(plain instanceof com.sun.management.ThreadMXBean);
        com.sun.management.ThreadMXBean bean = (com.sun.management.ThreadMXBean) plain;
        assumeTrue(bean.isThreadAllocatedMemorySupported() && bean.isThreadAllocatedMemoryEnabled());

        int n = 500;
        BroadPhase bp = new BroadPhase(2f);
        Random rnd = new Random(5);
        float[] baseX = new float[n];
        float[] baseY = new float[n];
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            baseX[i] = rnd.nextFloat() * 400f;
            baseY[i] = rnd.nextFloat() * 400f;
            ids[i] = bp.createProxy(baseX[i], baseY[i], baseX[i] + 10f, baseY[i] + 10f, i);
        }
        Counter counter = new Counter();
        for (int warm = 0; warm < 20; warm++) {
            period(bp, baseX, baseY, ids, counter);
        }
        long tid = Thread.currentThread().getId();
        long t0 = bean.getThreadAllocatedBytes(tid);
        long t1 = bean.getThreadAllocatedBytes(tid);
        period(bp, baseX, baseY, ids, counter);
        long t2 = bean.getThreadAllocatedBytes(tid);
        assertEquals(t1 - t0, t2 - t1, "bytes allocated during one period of the scene");
        assertTrue(counter.sum != 0);
        bp.validate();
    }
}
