package org.emini.dynamics;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * The brute-force model of the world's queries, in double precision and independent of the
 * engine's geometry: every convex piece (a polygon, a circle, a landscape segment, a ray, a swept
 * shape) is a convex core (a point, a segment or a polygon) grown by a radius, and everything is
 * decided by the exact signed distance between two pieces: the distance when they are apart, minus
 * the depth of overlap (the least translation that separates them) when they overlap.
 *
 * <p>A translation sweeps a convex piece over the convex hull of its start and end, so "the moving
 * shape touches Y before fraction t" is "the hull swept up to t overlaps Y": checks of a cast need
 * no time stepping and are exact.
 */
final class QueryModel {
    private QueryModel() {
    }

    /** A convex core (1 vertex: a point, 2: a segment, 3 or more: a polygon) grown by r. */
    static final class Convex {
        final double[] x;
        final double[] y;
        final double r;

        Convex(double[] x, double[] y, double r) {
            this.x = x;
            this.y = y;
            this.r = r;
        }

        int n() {
            return x.length;
        }

        /** The largest projection on a direction (the support function). */
        double support(double ux, double uy) {
            double best = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < x.length; i++) {
                best = Math.max(best, ux * x[i] + uy * y[i]);
            }
            return best + r * Math.hypot(ux, uy);
        }

        @Override
        public String toString() {
            return "Convex" + Arrays.toString(x) + Arrays.toString(y) + " r " + r;
        }
    }

    static Convex point(double x, double y) {
        return new Convex(new double[] {x}, new double[] {y}, 0);
    }

    static Convex segment(double x1, double y1, double x2, double y2) {
        if (x1 == x2 && y1 == y2) {
            return point(x1, y1);
        }
        return new Convex(new double[] {x1, x2}, new double[] {y1, y2}, 0);
    }

    /** The convex parts of a shape placed at (px, py) with rotation (c, s), in the world. */
    static List<Convex> parts(Shape shape, double px, double py, double c, double s) {
        List<Convex> out = new ArrayList<>();
        if (shape.getType() == Shape.TYPE_MULTI) {
            MultiShape m = (MultiShape) shape;
            for (int i = 0; i < m.getShapeCount(); i++) {
                out.add(part(m.getShape(i), px, py, c, s));
            }
        } else {
            out.add(part(shape, px, py, c, s));
        }
        return out;
    }

    static Convex part(Shape p, double px, double py, double c, double s) {
        if (p.getType() == Shape.TYPE_CIRCLE) {
            Circle k = (Circle) p;
            return new Convex(new double[] {px + c * k.getCenterX() - s * k.getCenterY()},
                new double[] {py + s * k.getCenterX() + c * k.getCenterY()}, k.getRadius());
        }
        Polygon poly = (Polygon) p;
        int n = poly.getVertexCount();
        double[] x = new double[n];
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = px + c * poly.getVertexX(i) - s * poly.getVertexY(i);
            y[i] = py + s * poly.getVertexX(i) + c * poly.getVertexY(i);
        }
        return new Convex(x, y, 0);
    }

    static List<Convex> bodyParts(Body b) {
        return parts(b.getShape(), b.getX(), b.getY(), b.getCos(), b.getSin());
    }

    static Convex translate(Convex a, double dx, double dy) {
        double[] x = a.x.clone();
        double[] y = a.y.clone();
        for (int i = 0; i < x.length; i++) {
            x[i] += dx;
            y[i] += dy;
        }
        return new Convex(x, y, a.r);
    }

    /** What a convex piece covers on its way along (dx, dy): the hull of its start and end. */
    static Convex sweep(Convex a, double dx, double dy) {
        int n = a.n();
        double[][] pts = new double[2 * n][];
        for (int i = 0; i < n; i++) {
            pts[i] = new double[] {a.x[i], a.y[i]};
            pts[n + i] = new double[] {a.x[i] + dx, a.y[i] + dy};
        }
        return hull(pts, a.r);
    }

    /** Andrew's monotone chain; collinear and repeated points dropped. */
    static Convex hull(double[][] pts, double r) {
        double[][] p = pts.clone();
        Arrays.sort(p, (u, v) -> u[0] != v[0] ? Double.compare(u[0], v[0]) : Double.compare(u[1], v[1]));
        double[][] h = new double[2 * p.length + 1][];
        int k = 0;
        for (double[] q : p) {
            while (k >= 2 && cross(h[k - 2], h[k - 1], q) <= 0) {
                k--;
            }
            h[k++] = q;
        }
        for (int i = p.length - 2, lower = k + 1; i >= 0; i--) {
            double[] q = p[i];
            while (k >= lower && cross(h[k - 2], h[k - 1], q) <= 0) {
                k--;
            }
            h[k++] = q;
        }
        int m = Math.max(1, k - 1);
        if (k <= 1) {
            m = 1;
        }
        // All points equal, or on one line: a point or a segment.
        double[] x = new double[m];
        double[] y = new double[m];
        for (int i = 0; i < m; i++) {
            x[i] = h[i][0];
            y[i] = h[i][1];
        }
        if (m == 2 && x[0] == x[1] && y[0] == y[1]) {
            return new Convex(new double[] {x[0]}, new double[] {y[0]}, r);
        }
        return new Convex(x, y, r);
    }

    private static double cross(double[] o, double[] a, double[] b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    }

    /** The exact signed distance of two pieces: apart &gt; 0, touching 0, overlapping −depth. */
    static double sd(Convex a, Convex b) {
        return sdCore(a, b) - a.r - b.r;
    }

    /** The separation along a unit axis u of a (on the +u side) from b: min a·u − max b·u. */
    static double separationAlong(Convex a, Convex b, double ux, double uy) {
        return -a.support(-ux, -uy) - b.support(ux, uy);
    }

    private static double sdCore(Convex a, Convex b) {
        Convex ca = new Convex(a.x, a.y, 0);
        Convex cb = new Convex(b.x, b.y, 0);
        if (a.n() == 1 && b.n() == 1) {
            return Math.hypot(a.x[0] - b.x[0], a.y[0] - b.y[0]);
        }
        // Separating axes: the faces of polygons, and a segment's normal and direction, both ways.
        double best = Double.NEGATIVE_INFINITY;
        for (Convex p : new Convex[] {ca, cb}) {
            for (double[] u : axes(p)) {
                best = Math.max(best, separationAlong(ca, cb, u[0], u[1]));
                best = Math.max(best, separationAlong(ca, cb, -u[0], -u[1]));
            }
        }
        if (best > 0 || best == Double.NEGATIVE_INFINITY) {
            return distance(ca, cb);
        }
        return best;
    }

    private static List<double[]> axes(Convex p) {
        List<double[]> out = new ArrayList<>();
        int n = p.n();
        if (n == 1) {
            return out;
        }
        for (int i = 0; i < n; i++) {
            int k = (i + 1) % n;
            double ex = p.x[k] - p.x[i];
            double ey = p.y[k] - p.y[i];
            double len = Math.hypot(ex, ey);
            if (len == 0) {
                continue;
            }
            out.add(new double[] {ey / len, -ex / len});
            if (n == 2) {
                out.add(new double[] {ex / len, ey / len});
                break;
            }
        }
        return out;
    }

    /** The distance between two disjoint cores: the nearest vertex–edge pair. */
    private static double distance(Convex a, Convex b) {
        return Math.min(vertexToEdges(a, b), vertexToEdges(b, a));
    }

    private static double vertexToEdges(Convex a, Convex b) {
        double best = Double.POSITIVE_INFINITY;
        int n = b.n();
        for (int i = 0; i < a.n(); i++) {
            if (n == 1) {
                best = Math.min(best, Math.hypot(a.x[i] - b.x[0], a.y[i] - b.y[0]));
                continue;
            }
            for (int j = 0; j < n; j++) {
                int k = (j + 1) % n;
                best = Math.min(best, pointSegment(a.x[i], a.y[i], b.x[j], b.y[j], b.x[k], b.y[k]));
            }
        }
        return best;
    }

    static double pointSegment(double px, double py, double x1, double y1, double x2, double y2) {
        double ex = x2 - x1;
        double ey = y2 - y1;
        double len2 = ex * ex + ey * ey;
        double t = len2 > 0 ? ((px - x1) * ex + (py - y1) * ey) / len2 : 0;
        t = Math.max(0, Math.min(1, t));
        return Math.hypot(px - x1 - t * ex, py - y1 - t * ey);
    }

    /** The smallest signed distance between any part of one list and any of another. */
    static double sd(List<Convex> a, List<Convex> b) {
        double best = Double.POSITIVE_INFINITY;
        for (Convex p : a) {
            for (Convex q : b) {
                best = Math.min(best, sd(p, q));
            }
        }
        return best;
    }

    static double sd(List<Convex> a, Convex b) {
        return sd(a, List.of(b));
    }

    static List<Convex> sweep(List<Convex> a, double dx, double dy) {
        List<Convex> out = new ArrayList<>();
        for (Convex p : a) {
            out.add(sweep(p, dx, dy));
        }
        return out;
    }

    static List<Convex> translate(List<Convex> a, double dx, double dy) {
        List<Convex> out = new ArrayList<>();
        for (Convex p : a) {
            out.add(translate(p, dx, dy));
        }
        return out;
    }

    /** The least separation over the pieces of a along u (a on the +u side of b). */
    static double separationAlong(List<Convex> a, Convex b, double ux, double uy) {
        double best = Double.POSITIVE_INFINITY;
        for (Convex p : a) {
            best = Math.min(best, separationAlong(p, b, ux, uy));
        }
        return best;
    }
}
