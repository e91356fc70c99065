package org.emini.harness.scenario;

import java.util.List;
import org.emini.harness.load.JsonPath;

/**
 * A metric the scene asks to record, with its options.
 *
 * @param kind which metric
 * @param aboutX angular momentum reference point (px)
 * @param aboutY angular momentum reference point (px)
 * @param walls tunnelling walls
 * @param bodies tunnelling bodies (empty: every dynamic body)
 * @param emitters particles: the emitters counted (empty: all)
 * @param regionMin particles: the region's least corner (px), or null without a region
 * @param regionMax particles: the region's greatest corner (px), or null without a region
 * @param path where it is requested (null when an expectation asked for it implicitly)
 * @param wholeShape tunnelling: watch every vertex of a body's shape as well as its centre ({@code points: shape})
 * @param pairs penetration: the pair filters expectations read ({@code between}), each adding its channels
 *     {@code penetration.max(A, B)}, {@code .mean(A, B)}, {@code .points(A, B)} after the three of the world
 */
public record MetricSpec(Kind kind, double aboutX, double aboutY, List<WallSpec> walls, List<String> bodies,
                         List<String> emitters, double[] regionMin, double[] regionMax, JsonPath path,
                         boolean wholeShape, List<PairSpec> pairs) {

    /** Metric kinds, named as in the scene files; each documented in scenarios/README.md. */
    public enum Kind { energy, linearMomentum, angularMomentum, penetration, constraintError, tunnelling, stability,
        particles, sleeping, jointLimits }

    /** A metric with no options. */
    public static MetricSpec plain(Kind kind, JsonPath path) {
        return new MetricSpec(kind, 0, 0, List.of(), List.of(), List.of(), null, null, path, false, List.of());
    }

    /** The same metric with these pair filters (penetration). */
    public MetricSpec withPairs(List<PairSpec> list) {
        return new MetricSpec(kind, aboutX, aboutY, walls, bodies, emitters, regionMin, regionMax, path, wholeShape,
                List.copyOf(list));
    }

    /**
     * The channels this metric fills, in trace order: its fixed ones, then each pair filter's.
     */
    public List<String> channels() {
        List<String> out = new java.util.ArrayList<>(Channels.OF_METRIC.get(kind));
        for (PairSpec p : pairs) {
            for (String q : Channels.PAIR_QUANTITIES) {
                out.add(Channels.pair(q, p.a(), p.b()));
            }
        }
        return out;
    }

    /**
     * A penetration pair filter: the pairs of which one body matches {@code a} and the other {@code b}
     * (a name, a group with {@code *}, or {@link Channels#LANDSCAPE}).
     *
     * @param a the first body or group
     * @param b the second body or group
     */
    public record PairSpec(String a, String b) {
    }

    /**
     * A tunnelling wall: a body (its long axis through its origin) or a fixed world segment.
     *
     * @param body the wall body's name, or null
     * @param from segment start (px), when no body
     * @param to segment end (px), when no body
     */
    public record WallSpec(String body, double[] from, double[] to) {
    }
}
