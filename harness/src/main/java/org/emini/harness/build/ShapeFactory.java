package org.emini.harness.build;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.emini.harness.scenario.ShapeSpec;
import org.emini.shape.Circle;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * Makes engine shapes from shape specs. A named shape becomes one engine shape shared by all its
 * bodies, as a program using the engine would do.
 *
 * <p>A multi-shape becomes an engine {@code MultiShape} whose parts are placed in its frame: each part
 * rotated by its {@code angle}, then moved by its {@code offset} (a circle by its centre, a polygon
 * vertex by vertex); a part that is itself a multi-shape gives its own parts, placed through both. Each
 * part weighs its own mass, scaled so that a nested multi-shape's parts add up to that multi-shape's
 * mass; the whole then gets the multi-shape's mass (by default the sum of its parts). The body rotates
 * about the frame's origin, which the scene states is the centre of mass: the parts are not moved to
 * their centroid.
 *
 * <p>Public so that the world fuzzer (org.emini.harness.fuzz.world) builds its shapes exactly as a
 * scene's are built, which its scene files rely on.
 */
public final class ShapeFactory {
    private final Map<ShapeSpec, Shape> made = new IdentityHashMap<>();

    /** The engine shape of a spec: made once, then the same object for every body that uses it. */
    public Shape shape(ShapeSpec spec) {
        Shape shape = made.get(spec);
        if (shape == null) {
            Shape s = Located.at(spec.path(), () -> spec.kind() == ShapeSpec.Kind.multiShape ? multi(spec) : create(spec));
            Located.at(spec.path().key("mass"), () -> s.setMass((float) spec.mass()));
            Located.at(spec.path().key("friction"), () -> s.setFriction((float) spec.friction()));
            Located.at(spec.path().key("elasticity"), () -> s.setElasticity((float) spec.elasticity()));
            made.put(spec, s);
            shape = s;
        }
        return shape;
    }

    private static Shape create(ShapeSpec spec) {
        switch (spec.kind()) {
            case circle:
                return Shape.createCircle((float) spec.radius());
            case rectangle:
                return Shape.createRectangle((float) spec.width(), (float) spec.height());
            case regularPolygon:
                return Shape.createRegularPolygon((float) spec.radius(), spec.sides());
            default: {
                float[] xy = new float[spec.vertices().size() * 2];
                for (int i = 0; i < spec.vertices().size(); i++) {
                    xy[2 * i] = (float) spec.vertices().get(i)[0];
                    xy[2 * i + 1] = (float) spec.vertices().get(i)[1];
                }
                return Shape.createPolygon(xy);
            }
        }
    }

    private static Shape multi(ShapeSpec spec) {
        List<Shape> parts = new ArrayList<>();
        place(spec, 0, 0, 0, 1, parts);
        return Shape.createMultiShape(parts.toArray(new Shape[0]));
    }

    /** Adds the convex parts of a shape placed by (ox, oy, angle), masses times scale. */
    private static void place(ShapeSpec spec, double ox, double oy, double angle, double scale, List<Shape> out) {
        if (spec.kind() == ShapeSpec.Kind.multiShape) {
            double total = 0;
            for (ShapeSpec.Part p : spec.parts()) {
                total += p.shape().mass();
            }
            double inner = total > 0 ? scale * spec.mass() / total : 0;
            double c = Math.cos(angle);
            double s = Math.sin(angle);
            for (ShapeSpec.Part p : spec.parts()) {
                place(p.shape(), ox + c * p.offsetX() - s * p.offsetY(), oy + s * p.offsetX() + c * p.offsetY(),
                        angle + p.angle(), inner, out);
            }
            return;
        }
        Shape base = Located.at(spec.path(), () -> create(spec));
        final Shape placed;
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        if (base instanceof Circle circle) {
            placed = Located.at(spec.path(), () -> new Circle(circle.getRadius(), (float) ox, (float) oy));
        } else {
            Polygon polygon = (Polygon) base;
            float[] xy = new float[2 * polygon.getVertexCount()];
            for (int i = 0; i < polygon.getVertexCount(); i++) {
                double x = polygon.getVertexX(i);
                double y = polygon.getVertexY(i);
                xy[2 * i] = (float) (ox + c * x - s * y);
                xy[2 * i + 1] = (float) (oy + s * x + c * y);
            }
            placed = Located.at(spec.path(), () -> Shape.createPolygon(xy));
        }
        Located.at(spec.path().key("mass"), () -> placed.setMass((float) (spec.mass() * scale)));
        out.add(placed);
    }
}
