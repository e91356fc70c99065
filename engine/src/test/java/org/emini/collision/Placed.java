package org.emini.collision;

import org.emini.shape.Circle;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * A shape at a pose, with its world geometry in double precision for brute-force checks that do
 * not reuse the collider's code.
 */
record Placed(Shape shape, float x, float y, float c, float s) {
    static Placed at(Shape shape, float x, float y, float angle) {
        return new Placed(shape, x, y, (float) Math.cos(angle), (float) Math.sin(angle));
    }

    Placed movedTo(float nx, float ny) {
        return new Placed(shape, nx, ny, c, s);
    }

    boolean isCircle() {
        return shape instanceof Circle;
    }

    double radius() {
        return ((Circle) shape).getRadius();
    }

    /** World centre of a circle. */
    double[] centre() {
        Circle k = (Circle) shape;
        return world(k.getCenterX(), k.getCenterY());
    }

    /** World vertices of a polygon, counter-clockwise. */
    double[][] vertices() {
        Polygon p = (Polygon) shape;
        double[][] v = new double[p.getVertexCount()][];
        for (int i = 0; i < v.length; i++) {
            v[i] = world(p.getVertexX(i), p.getVertexY(i));
        }
        return v;
    }

    double[] world(double lx, double ly) {
        return new double[] {x + c * lx - s * ly, y + s * lx + c * ly};
    }

    /** A world point strictly inside the shape: t ∈ [0, 1) of the way from the centroid. */
    double[] innerPoint(double t, int vertex, double angle) {
        if (isCircle()) {
            double[] o = centre();
            double r = t * radius();
            return new double[] {o[0] + r * Math.cos(angle), o[1] + r * Math.sin(angle)};
        }
        double[][] v = vertices();
        double[] g = world(shape.getCentroidX(), shape.getCentroidY());
        double[] w = v[vertex % v.length];
        return new double[] {g[0] + t * (w[0] - g[0]), g[1] + t * (w[1] - g[1])};
    }

    /** Smallest projection onto the unit axis (nx, ny). */
    double min(double nx, double ny) {
        if (isCircle()) {
            double[] o = centre();
            return o[0] * nx + o[1] * ny - radius();
        }
        double m = Double.POSITIVE_INFINITY;
        for (double[] w : vertices()) {
            m = Math.min(m, w[0] * nx + w[1] * ny);
        }
        return m;
    }

    /** Largest projection onto the unit axis (nx, ny). */
    double max(double nx, double ny) {
        return -min(-nx, -ny);
    }

    /** World bounding box: minX, minY, maxX, maxY. */
    double[] box() {
        return new double[] {min(1, 0), min(0, 1), max(1, 0), max(0, 1)};
    }

    double boundingRadius() {
        return shape.getBoundingRadius();
    }

    @Override
    public String toString() {
        return shape + " at (" + x + ", " + y + ") rot (" + c + ", " + s + ")";
    }
}
