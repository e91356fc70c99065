package org.emini.harness.fuzz.world;

/** A recipe being generated: adds bodies and pin joints with fresh ids (for the lane and smooth generators). */
final class RecipeDraft {
    final Recipe recipe = new Recipe();
    private int nextBody;
    private int nextOther;

    /** Adds a body (and its shape, the first time). */
    BodyRecipe body(ShapeRecipe shape, float x, float y, boolean dynamic) {
        if (recipe.shape(shape.id) == null) {
            recipe.shapes.add(shape);
        }
        BodyRecipe b = new BodyRecipe();
        b.id = nextBody++;
        b.shape = shape.id;
        b.x = x;
        b.y = y;
        b.dynamic = dynamic;
        recipe.bodies.add(b);
        return b;
    }

    /** Adds a pin joint of two bodies at a world point. */
    JointRecipe pin(BodyRecipe a, BodyRecipe b, float x, float y) {
        JointRecipe j = new JointRecipe();
        j.id = otherId();
        j.a = a.id;
        j.b = b.id;
        j.atPoint = true;
        j.x = x;
        j.y = y;
        recipe.joints.add(j);
        return j;
    }

    /** A fresh id for an element other than a body. */
    int otherId() {
        return nextOther++;
    }
}
