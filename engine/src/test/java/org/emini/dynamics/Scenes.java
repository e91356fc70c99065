package org.emini.dynamics;

import org.emini.shape.Polygon;
import org.emini.shape.Shape;
import org.emini.world.World;

/** Small scene builders shared by the physics tests. */
final class Scenes {
    private Scenes() {
    }

    /** A static ground box whose top surface is at y = top. */
    static Body ground(World world, float top, float width) {
        Body g = new Body(0f, top + 10f, Shape.createRectangle(width, 20f), false);
        world.addBody(g);
        return g;
    }

    /** A tower of square boxes standing on a ground whose top is y = 0; returns the boxes. */
    static Body[] tower(World world, int height, float size) {
        ground(world, 0f, 40f * size);
        Shape box = Shape.createRectangle(size, size);
        Body[] boxes = new Body[height];
        for (int i = 0; i < height; i++) {
            boxes[i] = new Body(0f, -size * 0.5f - i * size, box, true);
            world.addBody(boxes[i]);
        }
        return boxes;
    }

    /** A pyramid of square boxes with the given number of rows on a ground at y = 0. */
    static Body[] pyramid(World world, int rows, float size) {
        ground(world, 0f, 4f * rows * size);
        Shape box = Shape.createRectangle(size, size);
        Body[] boxes = new Body[rows * (rows + 1) / 2];
        int k = 0;
        for (int row = 0; row < rows; row++) {
            int n = rows - row;
            float x0 = -0.5f * (n - 1) * size;
            for (int j = 0; j < n; j++) {
                boxes[k] = new Body(x0 + j * size, -size * 0.5f - row * size, box, true);
                world.addBody(boxes[k++]);
            }
        }
        return boxes;
    }

    /**
     * A light 20 px box (mass 1) on a ground whose top is y = 0 and a 40 px box of the given mass
     * above it, its centre at heavyY (-40: resting on the light one); returns the light and the heavy.
     */
    static Body[] heavyOnLight(World world, float heavyMass, float heavyY) {
        ground(world, 0f, 400f);
        Body light = new Body(0f, -10f, Shape.createRectangle(20f, 20f), true);
        world.addBody(light);
        Polygon heavyShape = Shape.createRectangle(40f, 40f);
        heavyShape.setMass(heavyMass);
        Body heavy = new Body(0f, heavyY, heavyShape, true);
        world.addBody(heavy);
        return new Body[] {light, heavy};
    }

    static void run(World world, float seconds) {
        int ticks = (int) Math.round(seconds / world.getTimestep());
        for (int i = 0; i < ticks; i++) {
            world.tick();
        }
    }
}
