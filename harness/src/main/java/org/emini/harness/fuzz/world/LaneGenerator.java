package org.emini.harness.fuzz.world;

import org.emini.dynamics.Landscape;

/**
 * Separated worlds: two to six lanes 400 px apart, each with a 300 px floor (a static box, maybe tilted
 * up to 0.15 rad, or a landscape segment) and one dynamic thing: a body dropped from up to 250
 * px that lands flat or rolls, a body resting on the floor, or a pendulum of one or two links swinging
 * less than 0.4 rad. No dynamic body ever meets another, and none lands on a corner, so the motion is
 * not chaotic: it is what the dynamic-iteration, mirror and translation relations compare. (There are no
 * walls: a body hitting a wall corner-first makes the rest of its run depend on the last bits.)
 */
final class LaneGenerator {
    private static final float LANE = 400f;

    private final Rand rand;
    private final RecipeDraft draft = new RecipeDraft();
    private final Recipe r = draft.recipe;
    private final ShapeGenerator shapes;

    private LaneGenerator(Rand rand) {
        this.rand = rand;
        this.shapes = new ShapeGenerator(rand, false, 0);
    }

    static Recipe generate(Rand rand) {
        return new LaneGenerator(rand).build();
    }

    private Recipe build() {
        r.ticksPerSecond = rand.chance(0.5) ? 20 : 60;
        r.ticks = 3 * r.ticksPerSecond;
        r.iterations = rand.pick(4, 8, 10, 10, 16);
        if (rand.chance(0.3)) {
            r.gravityX = rand.length(-20, 20);
        }
        r.landscapeFriction = rand.factor(1);
        int lanes = rand.between(2, 6);
        for (int i = 0; i < lanes; i++) {
            lane(Rand.round((i - (lanes - 1) / 2.0) * LANE, Rand.LENGTH));
        }
        return r;
    }

    private void lane(float cx) {
        float floorY = rand.length(-20, 20);
        float tilt = rand.chance(0.5) ? rand.angle(-0.15, 0.15) : 0f;
        if (rand.chance(0.6)) {
            BodyRecipe floor = draft.body(shapes.box(300, 20), cx, floorY + 10, false);
            floor.angle = tilt;
        } else {
            float dy = (float) Math.tan(tilt) * 150f;
            SegmentRecipe s = new SegmentRecipe();
            s.id = draft.otherId();
            s.x1 = cx - 150;
            s.y1 = Rand.round(floorY - dy, Rand.LENGTH);
            s.x2 = cx + 150;
            s.y2 = Rand.round(floorY + dy, Rand.LENGTH);
            s.face = rand.chance(0.5) ? Landscape.FACE_NONE : Landscape.FACE_LEFT;
            r.segments.add(s);
        }
        double kind = rand.unit();
        if (kind < 0.6) {
            dropped(cx, floorY, tilt);
        } else if (kind < 0.75) {
            ShapeRecipe s = shapes.box(rand.length(8, 40), rand.length(8, 30));
            shapes.material(s, 0);
            BodyRecipe b = draft.body(s, cx, floorY - s.height / 2 - 0.5f, true);
            b.angle = tilt;
            b.vx = rand.length(-10, 10);
        } else {
            pendulum(cx, floorY - 250);
        }
    }

    /**
     * A body dropped from up to 250 px that lands without tipping on a corner (which would make the
     * motion depend on the last bits): a circle, or a box or regular polygon with a face parallel to
     * the floor (at most 6 sides, so it tips only beyond 0.52 rad), not spinning.
     */
    private void dropped(float cx, float floorY, float tilt) {
        ShapeRecipe s = switch (rand.between(0, 2)) {
            case 0 -> shapes.circle(6, 40);
            case 1 -> {
                // No taller than 1.2 times its width: a tall box tips on landing by a hair.
                float width = rand.length(6, 40);
                yield shapes.box(width, rand.length(6, 1.2 * width));
            }
            default -> shapes.regular(6, 40);
        };
        // A polygon of many sides on a slope rolls or not by a hair (it tips beyond π/n).
        s.sides = Math.min(s.sides, 6);
        shapes.material(s, 0.6);
        r.shapes.add(s);
        BodyRecipe b = draft.body(s, cx + rand.length(-20, 20), floorY - 40 - rand.length(0, 210), true);
        flags(b);
        b.angle = s.kind == ShapeRecipe.Kind.regularPolygon
                ? Rand.round(Math.PI / 2 - Math.PI / s.sides + tilt, Rand.ANGLE) : tilt;
        b.vx = rand.length(-10, 10);
    }

    /** A static pivot and one or two links hanging from it by joints (or a rigid spring for the first). */
    private void pendulum(float cx, float top) {
        BodyRecipe pivot = draft.body(shapes.box(6, 6), cx, top, false);
        BodyRecipe previous = pivot;
        float px = cx;
        float py = top;
        double angle = rand.angle(-0.4, 0.4);
        for (int i = rand.between(1, 2); i > 0; i--) {
            float length = rand.length(15, 30);
            float bx = Rand.round(px + length * Math.sin(angle), Rand.LENGTH);
            float by = Rand.round(py + length * Math.cos(angle), Rand.LENGTH);
            ShapeRecipe s = rand.chance(0.5) ? shapes.box(rand.length(4, 10), rand.length(4, 10)) : shapes.any(4, 10, 0);
            if (s.kind == ShapeRecipe.Kind.rectangle) {
                shapes.material(s, 0);
            }
            r.shapes.add(s);
            BodyRecipe b = draft.body(s, bx, by, true);
            if (previous == pivot && rand.chance(0.3)) {
                SpringRecipe sp = new SpringRecipe();
                sp.id = draft.otherId();
                sp.a = previous.id;
                sp.b = b.id;
                sp.collide = false;
                r.springs.add(sp);
            } else {
                draft.pin(previous, b, px, py);
            }
            previous = b;
            px = bx;
            py = by;
            angle += rand.angle(-0.2, 0.2);
        }
    }

    private void flags(BodyRecipe b) {
        b.bullet = rand.chance(0.1);
        b.rotatable = !rand.chance(0.1);
        b.gravity = !rand.chance(0.05);
    }

}
