package org.emini.harness.build;

import java.util.IdentityHashMap;
import java.util.Map;
import org.emini.harness.scenario.ShapeSpec;
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
            default:
                throw new UnsupportedElementException("shape type multiShape", spec.path());
        }
    }
}
