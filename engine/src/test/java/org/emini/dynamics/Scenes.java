package org.emini.dynamics;

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

    static void run(World world, float seconds) {
        int ticks = (int) Math.round(seconds / world.getTimestep());
        for (int i = 0; i < ticks; i++) {
            world.tick();
        }
    }
}
