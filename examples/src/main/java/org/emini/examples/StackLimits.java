package org.emini.examples;

import java.util.Random;
import org.emini.collision.Collider;
import org.emini.collision.Manifold;
import org.emini.dynamics.Body;
import org.emini.dynamics.Contact;
import org.emini.world.World;
import org.emini.shape.Shape;

/**
 * Measures how tall a tower of 20 px boxes and how many pyramid rows stand for 60 simulated
 * seconds (every box drifts less than 1 px sideways and turns less than 0.05 rad, neighbours overlap
 * by less than 0.5 px), at a tick rate, with the boxes placed exactly or shifted by up to ±0.1 px.
 *
 * <p>Usage: {@code StackLimits [ticksPerSecond] [iterations]} (defaults 20 and 10).
 */
public final class StackLimits {
    private static final float SIZE = 20f;

    private StackLimits() {
    }

    /**
     * Runs the measurement.
     *
     * @param args tick rate and iterations, both optional
     */
    public static void main(String[] args) {
        float tps = args.length > 0 ? Float.parseFloat(args[0]) : 20f;
        int iterations = args.length > 1 ? Integer.parseInt(args[1]) : 10;
        for (float jitter : new float[] {0f, 0.1f}) {
            int tower = 0;
            float towerOverlap = 0f;
            for (int n = 5; n <= 100; n += 5) {
                float overlap = run(tps, iterations, n, false, jitter);
                if (overlap < 0f) {
                    break;
                }
                tower = n;
                towerOverlap = overlap;
            }
            int rows = 0;
            float pyramidOverlap = 0f;
            for (int n = 10; n <= 60; n += 10) {
                float overlap = run(tps, iterations, n, true, jitter);
                if (overlap < 0f) {
                    break;
                }
                rows = n;
                pyramidOverlap = overlap;
            }
            System.out.printf("%.0f ticks/s, %d iterations, placement jitter ±%.1f px: tower of %d holds "
                + "(max overlap %.3f px), pyramid of %d rows holds (max overlap %.3f px)%n",
                tps, iterations, jitter, tower, towerOverlap, rows, pyramidOverlap);
        }
    }

    /** Returns the largest overlap seen, or −1 when the stack did not hold. */
    static float run(float tps, int iterations, int n, boolean pyramid, float jitter) {
        World world = new World();
        world.setTicksPerSecond(tps);
        world.setConstraintIterations(iterations);
        world.addBody(new Body(0f, SIZE * 0.5f, Shape.createRectangle(SIZE * 200f, SIZE), false));
        Shape box = Shape.createRectangle(SIZE, SIZE);
        Random random = new Random(n);
        int count = pyramid ? n * (n + 1) / 2 : n;
        Body[] boxes = new Body[count];
        float[] x0 = new float[count];
        int k = 0;
        for (int row = 0; row < n; row++) {
            int width = pyramid ? n - row : 1;
            for (int j = 0; j < width; j++) {
                float x = (j - 0.5f * (width - 1)) * SIZE + (random.nextFloat() * 2f - 1f) * jitter;
                boxes[k] = new Body(x, -SIZE * 0.5f - row * SIZE, box, true);
                world.addBody(boxes[k]);
                x0[k] = x;
                k++;
            }
        }
        Collider collider = new Collider();
        Manifold m = new Manifold();
        float worst = 0f;
        int ticks = Math.round(60f * tps);
        for (int t = 0; t < ticks; t++) {
            world.tick();
            for (int i = 0; i < count; i++) {
                if (Math.abs(boxes[i].getX() - x0[i]) >= 1f || Math.abs(boxes[i].getAngle()) >= 0.05f) {
                    return -1f;
                }
            }
            if (t % 10 == 0) {
                for (int c = 0; c < world.getContactCount(); c++) {
                    Contact contact = world.getContact(c);
                    Body a = contact.getBodyA();
                    Body b = contact.getBodyB();
                    collider.collide(a.getShape(), a.getX(), a.getY(), a.getCos(), a.getSin(),
                        b.getShape(), b.getX(), b.getY(), b.getCos(), b.getSin(), 0f, m);
                    for (int p = 0; p < m.pointCount; p++) {
                        worst = Math.max(worst, -m.separation[p]);
                    }
                }
                if (worst >= 0.5f) {
                    return -1f;
                }
            }
        }
        return worst;
    }
}
