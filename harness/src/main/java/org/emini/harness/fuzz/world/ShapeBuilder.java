package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.emini.harness.build.ShapeFactory;
import org.emini.harness.load.JsonPath;
import org.emini.harness.scenario.ShapeSpec;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * Engine shapes of a recipe, one per shape id (shared by the bodies that use it, as a scene's named
 * shapes are). Everything a scene can say goes through the harness's own {@link ShapeFactory}, so a
 * recipe and its scene file build the same shapes bit for bit; off-centre circles and
 * {@code centred()} are added here.
 */
final class ShapeBuilder {
    private final Recipe recipe;
    private final ShapeFactory factory = new ShapeFactory();
    private final Map<Integer, Shape> made = new HashMap<>();

    ShapeBuilder(Recipe recipe) {
        this.recipe = recipe;
    }

    Shape shape(int id) {
        return made.computeIfAbsent(id, k -> create(recipe.shape(k)));
    }

    private Shape create(ShapeRecipe r) {
        if (r == null) {
            throw new IllegalArgumentException("the recipe has no shape with that id");
        }
        Shape shape;
        if (r.offCentreCircle()) {
            shape = new Circle(r.radius, r.centerX, r.centerY);
            shape.setMass(r.mass);
            shape.setFriction(r.friction);
            shape.setElasticity(r.elasticity);
        } else {
            shape = factory.shape(spec(r));
        }
        if (r.centred && shape instanceof Polygon p) {
            shape = p.centred();
        } else if (r.centred && shape instanceof MultiShape m) {
            shape = m.centred();
        }
        return shape;
    }

    /** Whether the engine accepts the shape (a generated polygon may be narrower than Shape.MIN_SIZE). */
    static boolean accepted(ShapeRecipe s) {
        try {
            if (s.offCentreCircle()) {
                new Circle(s.radius, s.centerX, s.centerY);
            } else {
                new ShapeFactory().shape(spec(s));
            }
            return true;
        } catch (IllegalArgumentException e) {
            return false;
        }
    }

    /** The scene's form of a shape (what a scene file with these values reads into). */
    static ShapeSpec spec(ShapeRecipe r) {
        List<double[]> vertices = null;
        if (r.vertices != null) {
            vertices = new ArrayList<>();
            for (int i = 0; i + 1 < r.vertices.length; i += 2) {
                vertices.add(new double[] {r.vertices[i], r.vertices[i + 1]});
            }
        }
        List<ShapeSpec.Part> parts = new ArrayList<>();
        for (ShapeRecipe.Part p : r.parts) {
            parts.add(new ShapeSpec.Part(spec(p.shape), p.offsetX, p.offsetY, p.angle));
        }
        return new ShapeSpec(null, ShapeSpec.Kind.valueOf(r.kind.name()), r.radius, r.width, r.height, r.sides,
                vertices, parts, r.mass, r.friction, r.elasticity, JsonPath.ROOT);
    }
}
