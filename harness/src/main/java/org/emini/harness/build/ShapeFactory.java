package org.emini.harness.build;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.emini.harness.scenario.ShapeSpec;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * Makes engine shapes from shape specs. A named shape becomes one engine shape shared by all its
 * bodies, as a program using the engine would do.
 */
final class ShapeFactory {
    private final Map<ShapeSpec, Shape> made = new IdentityHashMap<>();

    Shape shape(ShapeSpec spec) throws UnsupportedElementException {
        Shape shape = made.get(spec);
        if (shape == null) {
            shape = create(spec);
            shape.setMass((float) spec.mass());
            shape.setFriction((float) spec.friction());
            shape.setElasticity((float) spec.elasticity());
            made.put(spec, shape);
        }
        return shape;
    }

    private static Shape create(ShapeSpec spec) throws UnsupportedElementException {
        switch (spec.kind()) {
            case circle:
                return Shape.createCircle((float) spec.radius());
            case rectangle:
                return Shape.createRectangle((float) spec.width(), (float) spec.height());
            case regularPolygon:
                return Shape.createRegularPolygon((float) spec.radius(), spec.sides());
            case polygon: {
                float[] xy = new float[spec.vertices().size() * 2];
                for (int i = 0; i < spec.vertices().size(); i++) {
                    xy[2 * i] = (float) spec.vertices().get(i)[0];
                    xy[2 * i + 1] = (float) spec.vertices().get(i)[1];
                }
                return Shape.createPolygon(xy);
            }
            case multiShape: {
                List<Shape> leaves = new ArrayList<>();
                for (ShapeSpec.Part part : spec.parts()) {
                    addParts(part.shape(), part.offsetX(), part.offsetY(), part.angle(), leaves);
                }
                return new MultiShape(leaves.toArray(new Shape[0]));
            }
            default:
                throw new UnsupportedElementException("shape type " + spec.kind(), spec.path());
        }
    }

    /**
     * Adds a multi-shape part, placed in the multi-shape's frame: turned by {@code angle} about its
     * origin, then moved by (dx, dy). A part that is itself a multi-shape gives its own parts, composed.
     * Each part keeps its own mass (the multi-shape's mass is their sum, unless the scene gives one).
     */
    private static void addParts(ShapeSpec spec, double dx, double dy, double angle, List<Shape> out)
            throws UnsupportedElementException {
        double c = Math.cos(angle), s = Math.sin(angle);
        if (spec.kind() == ShapeSpec.Kind.multiShape) {
            for (ShapeSpec.Part p : spec.parts()) {
                addParts(p.shape(), dx + c * p.offsetX() - s * p.offsetY(), dy + s * p.offsetX() + c * p.offsetY(),
                    angle + p.angle(), out);
            }
            return;
        }
        Shape part;
        if (spec.kind() == ShapeSpec.Kind.circle) {
            part = new Circle((float) spec.radius(), (float) dx, (float) dy);
        } else {
            Polygon local = (Polygon) create(spec);
            float[] xy = new float[2 * local.getVertexCount()];
            for (int i = 0; i < local.getVertexCount(); i++) {
                double x = local.getVertexX(i), y = local.getVertexY(i);
                xy[2 * i] = (float) (dx + c * x - s * y);
                xy[2 * i + 1] = (float) (dy + s * x + c * y);
            }
            part = dx == 0 && dy == 0 && angle == 0 ? local : new Polygon(xy);
        }
        part.setMass((float) spec.mass());
        out.add(part);
    }
}
