package org.emini.harness.metrics;

/** Segment geometry for the tunnelling monitor. */
final class Segments {
    private Segments() {
    }

    /**
     * Whether the path p→q strictly crosses the line segment a→b: p and q lie strictly on opposite
     * sides of the line, and a and b do not lie strictly on the same side of the path. A path that only
     * touches the line does not count.
     */
    static boolean cross(double px, double py, double qx, double qy, double ax, double ay, double bx, double by) {
        double d1 = orient(ax, ay, bx, by, px, py);
        double d2 = orient(ax, ay, bx, by, qx, qy);
        if (!(d1 < 0 && d2 > 0 || d1 > 0 && d2 < 0)) {
            return false;
        }
        double d3 = orient(px, py, qx, qy, ax, ay);
        double d4 = orient(px, py, qx, qy, bx, by);
        return d3 <= 0 && d4 >= 0 || d3 >= 0 && d4 <= 0;
    }

    /** The side of the line a→b a point is on: −1, 0 (on the line) or 1. */
    static int side(double ax, double ay, double bx, double by, double px, double py) {
        return (int) Math.signum(orient(ax, ay, bx, by, px, py));
    }

    private static double orient(double ax, double ay, double bx, double by, double cx, double cy) {
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    }
}
