package org.emini.harness.fuzz.world;

import org.emini.dynamics.Landscape;

/**
 * The static part of a general world: a floor (a static box, a landscape chain with faces, or both),
 * maybe walls, floating platforms and static obstacles, and maybe a non-interacting static sensor.
 * The floor's top is near y = 0; bodies fall toward +y.
 */
final class ArenaGenerator {
    private final Rand rand;
    private final Recipe recipe;
    private final Placement placement;
    private final ShapeGenerator shapes;
    private int nextBody;
    private int nextSegment;

    ArenaGenerator(Rand rand, Recipe recipe, Placement placement, ShapeGenerator shapes, int firstBodyId) {
        this.rand = rand;
        this.recipe = recipe;
        this.placement = placement;
        this.shapes = shapes;
        this.nextBody = firstBodyId;
    }

    /** Builds the arena; returns its half width (bodies go inside it). */
    float build() {
        float half = rand.length(250, 450);
        double kind = rand.unit();
        if (kind < 0.5 || kind >= 0.85) {
            float height = rand.length(10, 40);
            BodyRecipe floor = staticBody(shapes.box(2 * half + 40, height), 0, height / 2);
            floor.angle = rand.chance(0.2) ? rand.angle(-0.1, 0.1) : 0f;
            placement.add(floor);
        }
        if (kind >= 0.5) {
            landscapeFloor(half);
        }
        if (rand.chance(0.5)) {
            for (int side = -1; side <= 1; side += 2) {
                if (rand.chance(0.5)) {
                    placement.add(staticBody(shapes.box(20, 500), side * (half + 10), -250));
                } else {
                    placement.add(segment(side * half, 0, side * half, -500, Landscape.FACE_NONE));
                }
            }
        }
        for (int i = rand.between(0, 2); i > 0; i--) {
            float x = rand.length(-half + 60, half - 120);
            float y = rand.length(-300, -80);
            int face = rand.chance(0.5) ? Landscape.FACE_NONE : rand.pick(Landscape.FACE_LEFT, Landscape.FACE_RIGHT);
            placement.add(segment(x, y, x + rand.length(40, 150), y + rand.length(-30, 30), face));
        }
        for (int i = rand.between(0, 3); i > 0; i--) {
            ShapeRecipe s = shapes.any(10, 80, 0);
            recipe.shapes.add(s);
            BodyRecipe b = staticBody(s, rand.length(-half + 40, half - 40), rand.length(-300, -60));
            b.angle = rand.angle(-Math.PI, Math.PI);
            placement.tryAdd(b);
        }
        if (rand.chance(0.3)) {
            BodyRecipe sensor = staticBody(shapes.box(rand.length(40, 200), rand.length(30, 120)),
                    rand.length(-half / 2, half / 2), rand.length(-200, -30));
            sensor.interacting = false;
            recipe.bodies.add(sensor);
        }
        recipe.landscapeFriction = rand.factor(1);
        return half;
    }

    /** A chain of 3 to 8 segments across the floor, rising and falling within 40 px; some faced. */
    private void landscapeFloor(float half) {
        int n = rand.between(3, 8);
        float x = -half;
        float y = rand.length(-30, 10);
        for (int i = 0; i < n; i++) {
            float nx = i == n - 1 ? half : Rand.round(-half + 2.0 * half * (i + 1) / n, Rand.LENGTH);
            float ny = rand.length(-40, 10);
            // FACE_LEFT on a segment drawn left to right is solid from above: a floor one can jump through.
            int face = rand.chance(0.7) ? Landscape.FACE_NONE : Landscape.FACE_LEFT;
            placement.add(segment(x, y, nx, ny, face));
            x = nx;
            y = ny;
        }
    }

    BodyRecipe staticBody(ShapeRecipe shape, float x, float y) {
        if (recipe.shape(shape.id) == null) {
            recipe.shapes.add(shape);
        }
        BodyRecipe b = new BodyRecipe();
        b.id = nextBody++;
        b.shape = shape.id;
        b.x = x;
        b.y = y;
        b.dynamic = false;
        return b;
    }

    SegmentRecipe segment(float x1, float y1, float x2, float y2, int face) {
        SegmentRecipe s = new SegmentRecipe();
        s.id = nextSegment++;
        s.x1 = x1;
        s.y1 = y1;
        s.x2 = x2;
        s.y2 = y2;
        s.face = face;
        return s;
    }

    int nextBodyId() {
        return nextBody;
    }
}
