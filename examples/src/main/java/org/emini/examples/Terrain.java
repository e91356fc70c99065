package org.emini.examples;

import java.util.Random;
import org.emini.dynamics.Body;
import org.emini.dynamics.Landscape;
import org.emini.world.World;
import org.emini.shape.MultiShape;
import org.emini.shape.Shape;

/**
 * Measures what the landscape and the simulation area cost, headless, and prints milliseconds per
 * tick (wall clock, after a warm-up; the median of several runs, since a shared machine is noisy).
 *
 * <ol>
 * <li>A hilly landscape of 10,000 segments carrying a rain of boxes, balls and L-shapes, against
 * the same terrain built from 10,000 static bodies.</li>
 * <li>A row of box stacks on a landscape floor, all simulated against a simulation area holding a
 * fixed 300 of them, for worlds of 2,000, 10,000 and 50,000 boxes, and a world of just those 300
 * boxes for reference.</li>
 * </ol>
 *
 * <p>Usage: {@code Terrain [runs]} (default 5).
 */
public final class Terrain {
    private Terrain() {
    }

    /**
     * Runs the measurements.
     *
     * @param args the number of runs per figure, optional
     */
    public static void main(String[] args) {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 5;
        System.out.println("landscape: 10,000 segments of 4 px, 300 bodies rained on, 20 ticks/s");
        for (boolean asBodies : new boolean[] {false, true}) {
            double[] rain = new double[runs];
            double[] rest = new double[runs];
            for (int r = 0; r < runs; r++) {
                World world = rain(asBodies);
                rain[r] = msPerTick(world, 200);
                rest[r] = msPerTick(world, 200);
            }
            System.out.printf("  terrain as %-20s falling %6.2f ms/tick, at rest %6.2f ms/tick%n",
                asBodies ? "10,000 static bodies" : "a landscape", median(rain), median(rest));
        }
        double[] empty = new double[runs];
        for (int r = 0; r < runs; r++) {
            World world = new World();
            world.setLandscape(hills(10_000));
            world.addBody(new Body(0f, -100f, Shape.createRectangle(12f, 8f), true));
            msPerTick(world, 200);
            empty[r] = msPerTick(world, 2000);
        }
        System.out.printf("  one body on the 10,000-segment landscape: %.4f ms/tick%n", median(empty));

        System.out.println("simulation area: stacks of 5 boxes on a landscape floor, 300 boxes inside the area");
        double[] alone = new double[runs];
        for (int r = 0; r < runs; r++) {
            World world = stacks(300);
            msPerTick(world, 100);
            alone[r] = msPerTick(world, 200);
        }
        System.out.printf("  %6d boxes, no area (the reference)      %6.3f ms/tick%n", 300, median(alone));
        for (int total : new int[] {2_000, 10_000, 50_000}) {
            double[] all = new double[runs];
            double[] area = new double[runs];
            for (int r = 0; r < runs; r++) {
                World world = stacks(total);
                msPerTick(world, 60);
                all[r] = total <= 10_000 ? msPerTick(world, 40) : Double.NaN;
                world.setSimulationArea(-900f, -1000f, 900f, 1000f);
                msPerTick(world, 40);
                area[r] = msPerTick(world, 200);
                if (world.getSimulatedBodyCount() != 300) {
                    throw new IllegalStateException("expected 300 boxes inside, got " + world.getSimulatedBodyCount());
                }
            }
            System.out.printf("  %6d boxes: all simulated %8.2f ms/tick, 300 inside the area %6.3f ms/tick%n", total,
                median(all), median(area));
        }
    }

    private static double msPerTick(World world, int ticks) {
        long t0 = System.nanoTime();
        for (int t = 0; t < ticks; t++) {
            world.tick();
        }
        return (System.nanoTime() - t0) / 1e6 / ticks;
    }

    private static double median(double[] values) {
        double[] v = values.clone();
        java.util.Arrays.sort(v);
        return v[v.length / 2];
    }

    private static float height(float x) {
        return (float) (30 * Math.sin(x / 80.0) + 10 * Math.sin(x / 23.0));
    }

    private static Landscape hills(int segments) {
        Landscape l = new Landscape();
        float x0 = -2f * segments;
        for (int i = 0; i < segments; i++) {
            float a = x0 + 4f * i;
            l.addSegment(a, height(a), a + 4f, height(a + 4f));
        }
        return l;
    }

    /** 300 bodies over the middle of the hills; the hills as a landscape or as thin static boxes. */
    private static World rain(boolean asBodies) {
        World world = new World();
        if (asBodies) {
            float x0 = -2f * 10_000;
            for (int i = 0; i < 10_000; i++) {
                float a = x0 + 4f * i;
                float dx = 4f;
                float dy = height(a + 4f) - height(a);
                float len = (float) Math.sqrt(dx * dx + dy * dy);
                // A 1 px thick bar whose top face is the segment.
                Body bar = new Body(a + 2f, 0.5f * (height(a) + height(a + 4f)), Shape.createPolygon(
                    -len / 2, 0f, len / 2, 0f, len / 2, 1f, -len / 2, 1f), false);
                bar.setAngle((float) Math.atan2(dy, dx));
                world.addBody(bar);
            }
        } else {
            world.setLandscape(hills(10_000));
        }
        Random random = new Random(1);
        Shape[] shapes = {
            Shape.createRectangle(12f, 8f),
            Shape.createCircle(5f),
            new MultiShape(Shape.createRectangle(4f, 16f), Shape.createPolygon(2f, 4f, 12f, 4f, 12f, 8f, 2f, 8f)).centred(),
        };
        for (int i = 0; i < 300; i++) {
            Body b = new Body((random.nextFloat() * 2f - 1f) * 1500f, -80f - random.nextFloat() * 300f,
                shapes[i % shapes.length], true);
            b.setAngle(random.nextFloat() * 3f);
            world.addBody(b);
        }
        return world;
    }

    /** Stacks of five 20 px boxes, 30 px apart, centred on x = 0, on a landscape floor at y = 0. */
    private static World stacks(int boxes) {
        World world = new World();
        int columns = boxes / 5;
        float half = 15f * columns + 100f;
        Landscape floor = new Landscape();
        for (float x = -half; x < half; x += 100f) {
            floor.addSegment(x, 0f, x + 100f, 0f);
        }
        world.setLandscape(floor);
        Shape box = Shape.createRectangle(20f, 20f);
        for (int c = 0; c < columns; c++) {
            float x = -15f * columns + 30f * c + 15f;
            for (int k = 0; k < 5; k++) {
                world.addBody(new Body(x, -10f - 20f * k, box, true));
            }
        }
        return world;
    }
}
