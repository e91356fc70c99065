package org.emini.collision;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.Tuple;
import net.jqwik.api.constraints.IntRange;

/**
 * Random operation sequences checked against a brute-force model of the broadphase.
 */
class BroadPhaseProperties {

    sealed interface Op permits Create, Move, Destroy, Touch, SetStatic, Update {
    }

    record Create(float x, float y, float w, float h, boolean isStatic) implements Op {
    }

    record SetStatic(int pick, boolean isStatic) implements Op {
    }

    /** Translates by (dx, dy), resizes by (dw, dh), and announces displacement (vx, vy). */
    record Move(int pick, float dx, float dy, float dw, float dh, float vx, float vy)
            implements Op {
    }

    record Destroy(int pick) implements Op {
    }

    record Touch(int pick) implements Op {
    }

    record Update() implements Op {
    }

    private static Arbitrary<Float> quarters(int min, int max) {
        return Arbitraries.integers().between(min * 4, max * 4).map(i -> i / 4f);
    }

    @Provide
    Arbitrary<List<Op>> ops() {
        Arbitrary<Integer> pick = Arbitraries.integers().between(0, 1000);
        Arbitrary<Float> coord = quarters(0, 400);
        Arbitrary<Float> size = quarters(0, 40);
        Arbitrary<Float> small = quarters(-3, 3);
        Arbitrary<Float> large = quarters(-300, 300);
        Arbitrary<Float> resize = quarters(-2, 2);
        Arbitrary<Float> disp = quarters(-10, 10);
        Arbitrary<Float> zero = Arbitraries.just(0f);
        // About one proxy in four is static.
        Arbitrary<Boolean> isStatic = Arbitraries.integers().between(0, 3).map(i -> i == 0);
        Arbitrary<Op> create = Combinators.combine(coord, coord, size, size, isStatic)
                .as(Create::new);
        Arbitrary<Op> setStatic = Combinators.combine(pick, isStatic).as(SetStatic::new);
        Arbitrary<Op> smallMove = Combinators.combine(pick, small, small, zero, zero, disp, disp)
                .as(Move::new);
        Arbitrary<Op> largeMove = Combinators.combine(pick, large, large, resize, resize, disp,
                disp).as(Move::new);
        Arbitrary<Op> resizeMove = Combinators.combine(pick, zero, zero, resize, resize, zero,
                zero).as(Move::new);
        Arbitrary<Op> destroy = pick.map(Destroy::new);
        Arbitrary<Op> touch = pick.map(Touch::new);
        Arbitrary<Op> update = Arbitraries.just(new Update());
        return Arbitraries.frequencyOf(
                Tuple.of(5, create),
                Tuple.of(5, smallMove),
                Tuple.of(2, largeMove),
                Tuple.of(1, resizeMove),
                Tuple.of(2, destroy),
                Tuple.of(1, touch),
                Tuple.of(1, setStatic),
                Tuple.of(2, update)).list().ofMaxSize(200);
    }

    @Provide
    Arbitrary<Float> margins() {
        return Arbitraries.of(0f, 0.5f, 2f, 10f);
    }

    private static boolean overlap(float[] a, float[] b) {
        return a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];
    }

    private static void assertBalanced(BroadPhase bp) {
        int n = bp.getProxyCount();
        double bound = n == 0 ? 0 : 2.5 * Math.log(n) / Math.log(2) + 4;
        assertTrue(bp.getTreeHeight() <= bound,
                "height " + bp.getTreeHeight() + " for " + n + " proxies");
    }

    /**
     * Applies the operations to a broadphase while a brute-force model predicts every result;
     * returns a log of ids, move results and pairs.
     */
    static List<String> run(float margin, List<Op> ops) {
        BroadPhase bp = new BroadPhase(margin);
        List<String> log = new ArrayList<>();
        List<Integer> live = new ArrayList<>();
        Map<Integer, float[]> tight = new HashMap<>();
        Map<Integer, float[]> fat = new HashMap<>();
        Map<Integer, Integer> idOfUserData = new HashMap<>();
        Set<Integer> moved = new HashSet<>();
        Set<Integer> statics = new HashSet<>();
        Deque<Integer> freed = new ArrayDeque<>();
        int highWater = 0;
        int nextUserData = 1000;
        List<Op> all = new ArrayList<>(ops);
        all.add(new Update());

        for (Op op : all) {
            if (op instanceof Create c) {
                float[] t = {c.x(), c.y(), c.x() + c.w(), c.y() + c.h()};
                int userData = nextUserData;
                nextUserData += 7;
                int id = c.isStatic() ? bp.createProxy(t[0], t[1], t[2], t[3], userData, true)
                        : bp.createProxy(t[0], t[1], t[2], t[3], userData);
                int expectedId = freed.isEmpty() ? highWater++ : freed.pop();
                assertEquals(expectedId, id, "createProxy id");
                live.add(id);
                if (c.isStatic()) {
                    statics.add(id);
                }
                tight.put(id, t);
                fat.put(id, new float[] {t[0] - margin, t[1] - margin, t[2] + margin,
                    t[3] + margin});
                idOfUserData.put(userData, id);
                moved.add(id);
                log.add("c" + id);
            } else if (op instanceof Move m) {
                if (live.isEmpty()) {
                    continue;
                }
                int id = live.get(m.pick() % live.size());
                float[] o = tight.get(id);
                float w = Math.max(0f, o[2] - o[0] + m.dw());
                float h = Math.max(0f, o[3] - o[1] + m.dh());
                float[] t = {o[0] + m.dx(), o[1] + m.dy(), 0, 0};
                t[2] = t[0] + w;
                t[3] = t[1] + h;
                float[] f = fat.get(id);
                // The documented rule: re-insert when the tight box swept by the displacement left
                // the fat one, or when the fat one exceeds the new fat box by more than 4 margins
                // plus the stretch.
                float ex = BroadPhase.DISPLACEMENT_MULTIPLIER * m.vx();
                float ey = BroadPhase.DISPLACEMENT_MULTIPLIER * m.vy();
                float[] nf = {t[0] - margin, t[1] - margin, t[2] + margin, t[3] + margin};
                if (ex < 0f) {
                    nf[0] += ex;
                } else {
                    nf[2] += ex;
                }
                if (ey < 0f) {
                    nf[1] += ey;
                } else {
                    nf[3] += ey;
                }
                boolean inside = f[0] <= t[0] + Math.min(0f, m.vx()) && f[1] <= t[1] + Math.min(0f, m.vy())
                        && t[2] + Math.max(0f, m.vx()) <= f[2] && t[3] + Math.max(0f, m.vy()) <= f[3];
                float sx = 4f * margin + Math.abs(ex);
                float sy = 4f * margin + Math.abs(ey);
                boolean snug = nf[0] - sx <= f[0] && nf[1] - sy <= f[1] && f[2] <= nf[2] + sx
                        && f[3] <= nf[3] + sy;
                boolean result = bp.moveProxy(id, t[0], t[1], t[2], t[3], m.vx(), m.vy());
                assertEquals(!(inside && snug), result, "moveProxy result");
                tight.put(id, t);
                if (result) {
                    fat.put(id, nf);
                    moved.add(id);
                }
                float[] g = fat.get(id);
                assertTrue(g[0] <= t[0] + Math.min(0f, m.vx()) && g[1] <= t[1] + Math.min(0f, m.vy())
                        && t[2] + Math.max(0f, m.vx()) <= g[2] && t[3] + Math.max(0f, m.vy()) <= g[3],
                        "fat AABB encloses the tight one swept by the displacement");
                log.add("m" + id + result);
            } else if (op instanceof Destroy d) {
                if (live.isEmpty()) {
                    continue;
                }
                int id = live.remove(d.pick() % live.size());
                bp.destroyProxy(id);
                tight.remove(id);
                fat.remove(id);
                moved.remove(id);
                statics.remove(id);
                freed.push(id);
                log.add("d" + id);
            } else if (op instanceof Touch t) {
                if (live.isEmpty()) {
                    continue;
                }
                int id = live.get(t.pick() % live.size());
                bp.touchProxy(id);
                moved.add(id);
            } else if (op instanceof SetStatic ss) {
                if (live.isEmpty()) {
                    continue;
                }
                int id = live.get(ss.pick() % live.size());
                bp.setStatic(id, ss.isStatic());
                // A proxy that changes kind is moved (to the other tree) and its pairs reported.
                if (ss.isStatic() ? statics.add(id) : statics.remove(id)) {
                    moved.add(id);
                }
                log.add("s" + id + ss.isStatic());
            } else {
                List<int[]> reported = new ArrayList<>();
                bp.updatePairs((a, b) -> reported.add(new int[] {a, b}));
                List<String> actual = new ArrayList<>();
                for (int[] pair : reported) {
                    int a = idOfUserData.get(pair[0]);
                    int b = idOfUserData.get(pair[1]);
                    actual.add(a + "-" + b);
                    log.add(pair[0] + "-" + pair[1]);
                }
                List<String> expected = new ArrayList<>();
                List<Integer> ids = new ArrayList<>(new TreeSet<>(live));
                for (int i = 0; i < ids.size(); i++) {
                    for (int j = i + 1; j < ids.size(); j++) {
                        int a = ids.get(i);
                        int b = ids.get(j);
                        if ((moved.contains(a) || moved.contains(b))
                                && !(statics.contains(a) && statics.contains(b))
                                && overlap(fat.get(a), fat.get(b))) {
                            expected.add(a + "-" + b);
                        }
                    }
                }
                assertEquals(expected, actual, "pairs");
                moved.clear();
                bp.validate();
                assertBalanced(bp);
                log.add("h" + bp.getTreeHeight());
            }

            assertEquals(live.size(), bp.getProxyCount());
            assertEquals(moved.size(), bp.getMoveCount());
            for (int id : live) {
                float[] f = fat.get(id);
                assertArrayEquals(f, new float[] {bp.getFatMinX(id), bp.getFatMinY(id),
                    bp.getFatMaxX(id), bp.getFatMaxY(id)}, "fat AABB of " + id);
                assertEquals(moved.contains(id), bp.isMoved(id));
                assertEquals(statics.contains(id), bp.isStatic(id));
            }
        }
        bp.validate();
        return log;
    }

    @Property(tries = 300)
    void pairsMatchBruteForceAndInvariantsHold(@ForAll("margins") float margin,
            @ForAll("ops") List<Op> ops) {
        run(margin, ops);
    }

    @Property(tries = 100)
    void sameOperationsGiveIdenticalResults(@ForAll("margins") float margin,
            @ForAll("ops") List<Op> ops) {
        assertEquals(run(margin, ops), run(margin, ops));
    }

    @Property(tries = 50)
    void heightIsLogarithmicForRandomInserts(@ForAll @IntRange(min = 1, max = 3000) int n,
            @ForAll long seed) {
        Random rnd = new Random(seed);
        BroadPhase bp = new BroadPhase(1f);
        for (int i = 0; i < n; i++) {
            float x = rnd.nextFloat() * 1000f;
            float y = rnd.nextFloat() * 1000f;
            // Mostly small boxes, a few huge ones.
            float s = rnd.nextInt(20) == 0 ? rnd.nextFloat() * 500f : rnd.nextFloat() * 10f;
            bp.createProxy(x, y, x + s, y + s, i);
        }
        bp.validate();
        assertBalanced(bp);
        // Destroying a random half keeps it balanced.
        for (int i = 0; i < n; i++) {
            if (rnd.nextBoolean()) {
                bp.destroyProxy(i);
            }
        }
        bp.validate();
        assertBalanced(bp);
    }

    @Property(tries = 100)
    void queryMatchesBruteForce(@ForAll @IntRange(min = 0, max = 300) int n, @ForAll long seed) {
        Random rnd = new Random(seed);
        BroadPhase bp = new BroadPhase(rnd.nextFloat() * 3f);
        boolean[] isStatic = new boolean[n];
        for (int i = 0; i < n; i++) {
            float x = rnd.nextFloat() * 500f;
            float y = rnd.nextFloat() * 500f;
            isStatic[i] = rnd.nextInt(3) == 0;
            bp.createProxy(x, y, x + rnd.nextFloat() * 30f, y + rnd.nextFloat() * 30f, i,
                    isStatic[i]);
        }
        for (int q = 0; q < 20; q++) {
            float x = rnd.nextFloat() * 600f - 50f;
            float y = rnd.nextFloat() * 600f - 50f;
            float[] box = {x, y, x + rnd.nextFloat() * 100f, y + rnd.nextFloat() * 100f};
            TreeMap<Integer, Integer> found = new TreeMap<>();
            bp.query(box[0], box[1], box[2], box[3], id -> {
                found.merge(id, 1, Integer::sum);
                return true;
            });
            Set<Integer> expected = new TreeSet<>();
            for (int id = 0; id < n; id++) {
                float[] f = {bp.getFatMinX(id), bp.getFatMinY(id), bp.getFatMaxX(id),
                    bp.getFatMaxY(id)};
                if (overlap(f, box)) {
                    expected.add(id);
                }
            }
            assertEquals(expected, found.keySet());
            for (int count : found.values()) {
                assertEquals(1, count, "each proxy reported once");
            }
            for (int kind = 0; kind < 2; kind++) {
                boolean wantStatic = kind == 0;
                Set<Integer> some = new TreeSet<>();
                QueryCallback collect = id -> {
                    assertTrue(some.add(id), "each proxy reported once");
                    return true;
                };
                if (wantStatic) {
                    bp.queryStatic(box[0], box[1], box[2], box[3], collect);
                } else {
                    bp.queryDynamic(box[0], box[1], box[2], box[3], collect);
                }
                Set<Integer> expectedKind = new TreeSet<>();
                for (int id : expected) {
                    if (isStatic[id] == wantStatic) {
                        expectedKind.add(id);
                    }
                }
                assertEquals(expectedKind, some, wantStatic ? "static" : "dynamic");
            }
        }
    }
}
