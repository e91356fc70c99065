package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.List;
import org.emini.shape.Shape;

/**
 * Places bodies so that no two start overlapping (bounding boxes apart by a margin), nor a body and
 * a landscape segment: every generated world starts without overlap, so the overlap, pass-through
 * and energy checks need no exception for bodies born inside each other.
 */
final class Placement {
    private final Recipe recipe;
    private final ShapeBuilder shapes;
    private final float margin;
    private final List<float[]> boxes = new ArrayList<>();

    Placement(Recipe recipe, float margin) {
        this.recipe = recipe;
        this.shapes = new ShapeBuilder(recipe);
        this.margin = margin;
    }

    /** The body's bounding box where it stands. */
    float[] box(BodyRecipe b) {
        Shape s = shapes.shape(b.shape);
        float[] box = new float[4];
        s.computeAabb(b.x, b.y, (float) Math.cos(b.angle), (float) Math.sin(b.angle), box);
        return box;
    }

    /** Adds the body to the recipe if it overlaps nothing placed so far. */
    boolean tryAdd(BodyRecipe b) {
        float[] box = box(b);
        if (!free(box)) {
            return false;
        }
        boxes.add(box);
        recipe.bodies.add(b);
        return true;
    }

    /** Adds the body to the recipe whatever it overlaps (floors, sensors), and keeps others off it. */
    void add(BodyRecipe b) {
        boxes.add(box(b));
        recipe.bodies.add(b);
    }

    /** Adds a landscape segment and keeps bodies off its box. */
    void add(SegmentRecipe s) {
        boxes.add(new float[] {Math.min(s.x1, s.x2), Math.min(s.y1, s.y2), Math.max(s.x1, s.x2), Math.max(s.y1, s.y2)});
        recipe.segments.add(s);
    }

    /** Keeps bodies off a box (a body placed elsewhere that may not be overlapped). */
    void reserve(float[] box) {
        boxes.add(box);
    }

    private boolean free(float[] box) {
        for (float[] o : boxes) {
            if (box[0] - margin < o[2] && o[0] < box[2] + margin && box[1] - margin < o[3] && o[1] < box[3] + margin) {
                return false;
            }
        }
        return true;
    }
}
