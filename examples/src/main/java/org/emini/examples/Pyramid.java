package org.emini.examples;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;

/**
 * Builds a pyramid of 20 px boxes at the original engine's defaults (20 ticks per second,
 * 10 iterations), runs it headless and prints how far the boxes moved.
 *
 * <p>Usage: {@code Pyramid [rows] [seconds]} (defaults 20 rows, 60 s).
 */
public final class Pyramid {
    private Pyramid() {
    }

    /**
     * Runs the example.
     *
     * @param args rows and seconds, both optional
     */
    public static void main(String[] args) {
        int rows = args.length > 0 ? Integer.parseInt(args[0]) : 20;
        float seconds = args.length > 1 ? Float.parseFloat(args[1]) : 60f;
        World world = new World();
        world.addBody(new Body(0f, 10f, Shape.createRectangle(rows * 60f, 20f), false));
        Shape box = Shape.createRectangle(20f, 20f);
        int count = rows * (rows + 1) / 2;
        Body[] boxes = new Body[count];
        float[] startX = new float[count];
        float[] startY = new float[count];
        int k = 0;
        for (int row = 0; row < rows; row++) {
            int n = rows - row;
            for (int j = 0; j < n; j++) {
                Body b = new Body((j - 0.5f * (n - 1)) * 20f, -10f - row * 20f, box, true);
                world.addBody(b);
                startX[k] = b.getX();
                startY[k] = b.getY();
                boxes[k++] = b;
            }
        }
        int ticks = Math.round(seconds / world.getTimestep());
        long t0 = System.nanoTime();
        for (int t = 0; t < ticks; t++) {
            world.tick();
        }
        double ms = (System.nanoTime() - t0) / 1e6;
        float drift = 0f;
        float sag = 0f;
        float turn = 0f;
        for (int i = 0; i < count; i++) {
            drift = Math.max(drift, Math.abs(boxes[i].getX() - startX[i]));
            sag = Math.max(sag, boxes[i].getY() - startY[i]);
            turn = Math.max(turn, Math.abs(boxes[i].getAngle()));
        }
        System.out.printf("pyramid: %d rows, %d boxes, %d ticks of %.4f s, %d iterations%n",
            rows, count, ticks, world.getTimestep(), world.getConstraintIterations());
        System.out.printf("largest sideways drift %.3f px, largest sag %.3f px, largest turn %.4f rad%n", drift, sag, turn);
        System.out.printf("contacts %d, %.3f ms per tick (wall clock, includes JIT warm-up)%n",
            world.getContactCount(), ms / ticks);
        System.out.println(drift < 1f && turn < 0.05f ? "the pyramid stands" : "the pyramid fell");
    }
}
