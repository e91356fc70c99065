package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/** The same world with the same inputs gives bit-identical results. */
class DeterminismTest {
    static World rain(long seed) {
        Random random = new Random(seed);
        World world = new World();
        Scenes.ground(world, 0f, 600f);
        world.addBody(new Body(-300f, -150f, Shape.createRectangle(20f, 300f), false));
        world.addBody(new Body(300f, -150f, Shape.createRectangle(20f, 300f), false));
        Shape[] shapes = {Shape.createRectangle(14f, 10f), Shape.createCircle(6f), Shape.createRegularPolygon(8f, 6)};
        for (int i = 0; i < 150; i++) {
            Body b = new Body(random.nextFloat() * 500f - 250f, -50f - random.nextFloat() * 600f, shapes[i % 3], true);
            b.setAngle(random.nextFloat() * 3f);
            world.addBody(b);
        }
        return world;
    }

    static long hash(World world) {
        long h = 1125899906842597L;
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            h = 31 * h + Float.floatToIntBits(b.getX());
            h = 31 * h + Float.floatToIntBits(b.getY());
            h = 31 * h + Float.floatToIntBits(b.getAngle());
            h = 31 * h + Float.floatToIntBits(b.getVelocityX());
            h = 31 * h + Float.floatToIntBits(b.getVelocityY());
            h = 31 * h + Float.floatToIntBits(b.getAngularVelocity());
        }
        return h;
    }

    @Test
    void twoRunsOfTheSameSceneAreBitIdentical() {
        World a = rain(7);
        World b = rain(7);
        for (int t = 0; t < 300; t++) {
            a.tick();
            b.tick();
            if (t % 50 == 0) {
                assertEquals(hash(a), hash(b), "tick " + t);
            }
        }
        assertEquals(hash(a), hash(b));
    }

    @Test
    void landscapeMultiShapesAndAMovingAreaAreBitIdenticalToo() {
        World a = Terrain.rain(3000, 120, 1000f, 9);
        World b = Terrain.rain(3000, 120, 1000f, 9);
        for (int t = 0; t < 300; t++) {
            float x = -1200f + 8f * t;
            a.setSimulationArea(x, -1000f, x + 800f, 1000f);
            b.setSimulationArea(x, -1000f, x + 800f, 1000f);
            a.tick();
            b.tick();
        }
        assertEquals(hash(a), hash(b));
    }
}
