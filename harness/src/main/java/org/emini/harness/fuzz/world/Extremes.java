package org.emini.harness.fuzz.world;

/**
 * Turns a general world extreme with one to three changes far outside a game's ranges: speeds up to
 * 10³⁰ px/s, bodies of 0.05 px or 5000 px, mass ratios of 10⁶, forces of 10⁹, gravity ×1000, a world
 * 10⁶ px from the origin, 1 or 200 iterations, a spring of stiffness 10⁹. The engine must either
 * keep the state finite or stop with its documented error; it may not fail in any other way.
 */
final class Extremes {
    private Extremes() {
    }

    static void apply(Rand rand, Recipe r) {
        for (int i = rand.between(1, 3); i > 0; i--) {
            change(rand, r, rand.between(0, 8));
        }
    }

    private static void change(Rand rand, Recipe r, int which) {
        BodyRecipe b = r.bodies.isEmpty() ? null : r.bodies.get((int) (rand.unit() * r.bodies.size()));
        if (b != null && !b.dynamic) {
            // Static bodies take no velocity.
            b = null;
        }
        switch (which) {
            case 0 -> {
                if (b != null) {
                    double scale = Math.pow(10, rand.between(3, 30));
                    // Twice on one body would pass 10³⁰ and even a float's range: an input no setter takes.
                    b.vx = atMostHuge(b.vx * scale);
                    b.vy = atMostHuge(b.vy * scale + scale);
                }
            }
            case 1 -> {
                ShapeRecipe s = r.shapes.get((int) (rand.unit() * r.shapes.size()));
                if (rand.chance(0.5)) {
                    shrink(s);
                } else {
                    scale(s, 100f);
                }
            }
            case 2 -> {
                ShapeRecipe s = r.shapes.get((int) (rand.unit() * r.shapes.size()));
                s.mass *= rand.chance(0.5) ? 1e6f : 1e-4f;
            }
            case 3 -> {
                r.gravityX *= 1000f;
                r.gravityY = r.gravityY * 1000f + 1000f;
            }
            case 4 -> r.forces.forEach(f -> {
                f.fx *= 1e7f;
                f.fy *= 1e7f;
                f.torque *= 1e7f;
            });
            case 5 -> r.motors.forEach(m -> {
                m.maxImpulse = 1e9f;
                m.omega *= 1e3f;
                m.vx *= 1e4f;
            });
            case 6 -> Transforms.translate(r, 1e6f, -1e6f);
            case 7 -> r.iterations = rand.chance(0.5) ? 1 : 200;
            default -> r.springs.forEach(s -> {
                s.hertz = 0f;
                s.stiffness = 1e9f;
            });
        }
    }

    private static float atMostHuge(double v) {
        return (float) Math.max(-1e30, Math.min(1e30, v));
    }

    /**
     * Halves a shape up to eight times (to 1/256), stopping at the last size the engine accepts
     * (Shape.MIN_SIZE across): the smallest bodies a world may hold, not values it refuses.
     */
    private static void shrink(ShapeRecipe s) {
        for (int i = 0; i < 8; i++) {
            scale(s, 0.5f);
            if (!ShapeBuilder.accepted(s)) {
                scale(s, 2f);
                return;
            }
        }
    }

    private static void scale(ShapeRecipe s, float k) {
        s.radius *= k;
        s.width *= k;
        s.height *= k;
        s.centerX *= k;
        s.centerY *= k;
        if (s.vertices != null) {
            for (int i = 0; i < s.vertices.length; i++) {
                s.vertices[i] *= k;
            }
        }
        for (ShapeRecipe.Part p : s.parts) {
            scale(p.shape, k);
            p.offsetX *= k;
            p.offsetY *= k;
        }
    }
}
