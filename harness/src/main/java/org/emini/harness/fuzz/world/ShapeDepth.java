package org.emini.harness.fuzz.world;

import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/** How deep a point lies inside a placed shape, and a point well inside a shape (its core). */
final class ShapeDepth {
    private ShapeDepth() {
    }

    /**
     * Depth of world point (px, py) inside the shape at (x, y) turned by (c, s): the distance to the
     * surface, positive inside, negative outside (for a multi-shape: its deepest part).
     */
    static double depth(Shape shape, float x, float y, float c, float s, double px, double py) {
        double dx = px - x;
        double dy = py - y;
        double lx = c * dx + s * dy;
        double ly = -s * dx + c * dy;
        return local(shape, lx, ly);
    }

    private static double local(Shape shape, double lx, double ly) {
        if (shape instanceof Circle circle) {
            return circle.getRadius() - Math.hypot(lx - circle.getCenterX(), ly - circle.getCenterY());
        }
        if (shape instanceof Polygon p) {
            double depth = Double.MAX_VALUE;
            for (int i = 0; i < p.getVertexCount(); i++) {
                double out = p.getNormalX(i) * (lx - p.getVertexX(i)) + p.getNormalY(i) * (ly - p.getVertexY(i));
                depth = Math.min(depth, -out);
            }
            return depth;
        }
        MultiShape m = (MultiShape) shape;
        double depth = -Double.MAX_VALUE;
        for (int i = 0; i < m.getShapeCount(); i++) {
            depth = Math.max(depth, local(m.getShape(i), lx, ly));
        }
        return depth;
    }

    /**
     * A local point inside the shape: the centroid of a convex shape, or of a multi-shape's largest
     * part (a concave shape's centroid, or a body's origin, may lie outside it).
     */
    static float[] core(Shape shape) {
        if (shape instanceof MultiShape m) {
            Shape largest = m.getShape(0);
            for (int i = 1; i < m.getShapeCount(); i++) {
                if (m.getShape(i).getArea() > largest.getArea()) {
                    largest = m.getShape(i);
                }
            }
            return core(largest);
        }
        return new float[] {shape.getCentroidX(), shape.getCentroidY()};
    }
}
