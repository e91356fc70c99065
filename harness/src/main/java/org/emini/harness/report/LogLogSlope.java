package org.emini.harness.report;

/**
 * The least-squares slope of log y against log x: how a cost grows with a size (1 is linear, 2
 * quadratic). Points with a non-positive x or y are left out, since they have no logarithm.
 */
public final class LogLogSlope {
    private double sx;
    private double sy;
    private double sxx;
    private double sxy;
    private int n;

    /** Adds a point (size x, cost y). */
    public void add(double x, double y) {
        if (!(x > 0) || !(y > 0) || Double.isInfinite(x) || Double.isInfinite(y)) {
            return;
        }
        double lx = Math.log(x);
        double ly = Math.log(y);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        n++;
    }

    /** The slope, or null with fewer than two points of different sizes. */
    public Double slope() {
        double d = n * sxx - sx * sx;
        if (n < 2 || !(d > 0)) {
            return null;
        }
        return (n * sxy - sx * sy) / d;
    }
}
