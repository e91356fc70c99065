package org.emini.collision;

import java.util.ArrayList;
import java.util.List;

/**
 * Penetration depth by brute force: the smallest overlap of the two shapes' projections over all
 * candidate axes (every edge normal of both polygons, recomputed from the world vertices; for a
 * circle also the axis from its centre to the other shape's nearest vertex, or between two
 * centres). Negative when the shapes are apart along some axis.
 */
final class BruteForce {
    private BruteForce() {
    }

    /** Candidate axes as {nx, ny, overlap}, overlap ascending. */
    static List<double[]> axes(Placed a, Placed b) {
        List<double[]> dirs = new ArrayList<>();
        addEdgeNormals(a, dirs);
        addEdgeNormals(b, dirs);
        addCentreAxes(a, b, dirs);
        addCentreAxes(b, a, dirs);
        List<double[]> out = new ArrayList<>();
        for (double[] d : dirs) {
            double overlap = Math.min(a.max(d[0], d[1]) - b.min(d[0], d[1]),
                    b.max(d[0], d[1]) - a.min(d[0], d[1]));
            out.add(new double[] {d[0], d[1], overlap});
        }
        out.sort((p, q) -> Double.compare(p[2], q[2]));
        return out;
    }

    static double depth(Placed a, Placed b) {
        return axes(a, b).get(0)[2];
    }

    /**
     * The gap between the smallest overlap and the smallest overlap on an axis that is not
     * (anti-)parallel to it: large when the contact axis is unambiguous.
     */
    static double ambiguityMargin(Placed a, Placed b) {
        if (a.isCircle() && b.isCircle()) {
            // The overlap grows from ra + rb − d on the centre axis to ra + rb across it.
            double[] p = a.centre();
            double[] q = b.centre();
            return Math.hypot(q[0] - p[0], q[1] - p[1]);
        }
        List<double[]> axes = axes(a, b);
        double[] best = axes.get(0);
        for (double[] other : axes) {
            double cross = best[0] * other[1] - best[1] * other[0];
            // The opposite direction competes too: two centrally symmetric shapes with nearly the
            // same centre overlap as deeply along −n as along n.
            boolean opposite = best[0] * other[0] + best[1] * other[1] < 0;
            if (Math.abs(cross) > 1e-4 || opposite) {
                return other[2] - best[2];
            }
        }
        return Double.POSITIVE_INFINITY;
    }

    private static void addEdgeNormals(Placed p, List<double[]> dirs) {
        if (p.isCircle()) {
            return;
        }
        double[][] v = p.vertices();
        for (int i = 0; i < v.length; i++) {
            double[] w = v[(i + 1) % v.length];
            double ex = w[0] - v[i][0];
            double ey = w[1] - v[i][1];
            double len = Math.hypot(ex, ey);
            dirs.add(new double[] {ey / len, -ex / len});
        }
    }

    private static void addCentreAxes(Placed circle, Placed other, List<double[]> dirs) {
        if (!circle.isCircle()) {
            return;
        }
        double[] o = circle.centre();
        double[] target;
        if (other.isCircle()) {
            target = other.centre();
        } else {
            target = null;
            double best = Double.POSITIVE_INFINITY;
            for (double[] w : other.vertices()) {
                double d = Math.hypot(w[0] - o[0], w[1] - o[1]);
                if (d < best) {
                    best = d;
                    target = w;
                }
            }
        }
        double dx = target[0] - o[0];
        double dy = target[1] - o[1];
        double len = Math.hypot(dx, dy);
        // Coincident centres: every axis gives the same overlap.
        dirs.add(len > 0 ? new double[] {dx / len, dy / len} : new double[] {0, 1});
    }
}
