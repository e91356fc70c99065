package org.emini.dynamics;

import java.util.Random;
import org.emini.shape.MultiShape;
import org.emini.shape.Shape;
import org.emini.world.World;

/** A large hilly landscape with a rain of mixed bodies, for the scale, allocation and determinism tests. */
final class Terrain {
    static final float STEP = 4f;

    private Terrain() {
    }

    /** The surface height at x (y grows downwards). */
    static float height(float x) {
        return (float) (30 * Math.sin(x / 80.0) + 10 * Math.sin(x / 23.0));
    }

    /** A chain of n segments of 4 px centred on x = 0. */
    static Landscape landscape(int n) {
        Landscape l = new Landscape();
        float x0 = -0.5f * n * STEP;
        for (int i = 0; i < n; i++) {
            float a = x0 + i * STEP;
            float b = a + STEP;
            l.addSegment(a, height(a), b, height(b));
        }
        return l;
    }

    /** The world: the terrain and count bodies (boxes, balls, L-shapes) dropped over x in ±spread. */
    static World rain(int segments, int count, float spread, long seed) {
        World world = new World();
        world.setLandscape(landscape(segments));
        Random r = new Random(seed);
        Shape[] shapes = {
            Shape.createRectangle(12f, 8f),
            Shape.createCircle(5f),
            new MultiShape(Shape.createRectangle(4f, 16f), Shape.createPolygon(2f, 4f, 12f, 4f, 12f, 8f, 2f, 8f)).centred(),
        };
        for (int i = 0; i < count; i++) {
            float x = (r.nextFloat() * 2f - 1f) * spread;
            Body b = new Body(x, -80f - r.nextFloat() * 300f, shapes[i % shapes.length], true);
            b.setAngle(r.nextFloat() * 3f);
            world.addBody(b);
        }
        return world;
    }
}
