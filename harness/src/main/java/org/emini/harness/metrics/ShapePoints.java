package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.List;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/** The points of a shape that whole-shape tunnelling watches, in the body's frame: polygon vertices, circle centres. */
final class ShapePoints {
    private ShapePoints() {
    }

    /** Every polygon vertex and every off-centre circle centre of the shape (parts of a multi-shape included). */
    static List<float[]> vertices(Shape shape) {
        List<float[]> out = new ArrayList<>();
        add(shape, out);
        return out;
    }

    private static void add(Shape shape, List<float[]> out) {
        if (shape instanceof Polygon p) {
            for (int i = 0; i < p.getVertexCount(); i++) {
                out.add(new float[] {p.getVertexX(i), p.getVertexY(i)});
            }
        } else if (shape instanceof MultiShape m) {
            for (int i = 0; i < m.getShapeCount(); i++) {
                add(m.getShape(i), out);
            }
        } else if (shape instanceof Circle c && (c.getCenterX() != 0f || c.getCenterY() != 0f)) {
            out.add(new float[] {c.getCenterX(), c.getCenterY()});
        }
    }
}
