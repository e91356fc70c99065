package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.emini.harness.scenario.Channels;
import org.emini.harness.scenario.MetricSpec;

/**
 * Penetration per pair of bodies (or a body and the landscape), named by the bodies' scene names: the
 * penetration metric feeds it every overlapping contact point of a sample, and it keeps each pair's
 * figures over the run and each pair filter's ({@code between}) figures of the sample.
 *
 * <p>Parties are numbered in the scene's creation order, the landscape last; a pair is keyed by its two
 * numbers, lower first, so a pair made of several contacts (multi-shape parts) is one pair.
 */
final class PairPenetration {
    private final String[] names;
    private final List<boolean[][]> filters = new ArrayList<>();
    /** This sample's pairs: key → {deepest, sum of depths, points}. */
    private final Map<Long, double[]> sample = new HashMap<>();
    /** The run's pairs: key → {deepest, sum of depths, points, samples}. */
    private final Map<Long, double[]> run = new HashMap<>();

    /**
     * @param bodies the scene's bodies in creation order (the landscape is party {@code bodies.size()})
     * @param pairs the pair filters whose channels the metric fills
     */
    PairPenetration(List<String> bodies, List<MetricSpec.PairSpec> pairs) {
        names = new String[bodies.size() + 1];
        for (int i = 0; i < bodies.size(); i++) {
            names[i] = bodies.get(i);
        }
        names[bodies.size()] = Channels.LANDSCAPE;
        for (MetricSpec.PairSpec p : pairs) {
            boolean[][] m = new boolean[2][names.length];
            for (int i = 0; i < names.length; i++) {
                m[0][i] = Channels.matches(p.a(), names[i]);
                m[1][i] = Channels.matches(p.b(), names[i]);
            }
            filters.add(m);
        }
    }

    /** The landscape's party number. */
    int landscape() {
        return names.length - 1;
    }

    /** Starts a sample. */
    void begin() {
        sample.clear();
    }

    /** One overlapping contact point of the sample, {@code depth} &gt; 0 deep, between parties a and b. */
    void point(int a, int b, double depth) {
        double[] s = sample.computeIfAbsent(key(a, b), k -> new double[3]);
        s[0] = Math.max(s[0], depth);
        s[1] += depth;
        s[2]++;
    }

    /**
     * Ends a sample: adds its pairs to the run's and writes each filter's max, mean and points (0 without a
     * matching pair) from {@code out[offset]} on.
     */
    void end(double[] out, int offset) {
        for (Map.Entry<Long, double[]> e : sample.entrySet()) {
            double[] s = e.getValue();
            double[] r = run.computeIfAbsent(e.getKey(), k -> new double[4]);
            r[0] = Math.max(r[0], s[0]);
            r[1] += s[1];
            r[2] += s[2];
            r[3]++;
        }
        int at = offset;
        for (boolean[][] m : filters) {
            double max = 0;
            double sum = 0;
            double points = 0;
            for (Map.Entry<Long, double[]> e : sample.entrySet()) {
                int a = (int) (e.getKey() >>> 32);
                int b = (int) (long) e.getKey();
                if ((m[0][a] && m[1][b]) || (m[1][a] && m[0][b])) {
                    double[] s = e.getValue();
                    max = Math.max(max, s[0]);
                    sum += s[1];
                    points += s[2];
                }
            }
            out[at++] = max;
            out[at++] = points == 0 ? 0 : sum / points;
            out[at++] = points;
        }
    }

    /** Every pair that overlapped at a sample, deepest first (then by name). */
    List<PenetrationPair> pairs() {
        List<PenetrationPair> out = new ArrayList<>();
        for (Map.Entry<Long, double[]> e : run.entrySet()) {
            double[] r = e.getValue();
            out.add(new PenetrationPair(names[(int) (e.getKey() >>> 32)], names[(int) (long) e.getKey()], r[0],
                    r[1] / r[2], (int) r[3]));
        }
        out.sort(Comparator.comparingDouble(PenetrationPair::max).reversed().thenComparing(PenetrationPair::a)
                .thenComparing(PenetrationPair::b));
        return out;
    }

    private static long key(int a, int b) {
        return ((long) Math.min(a, b) << 32) | Math.max(a, b);
    }
}
