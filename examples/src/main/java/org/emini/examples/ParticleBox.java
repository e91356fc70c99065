package org.emini.examples;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import org.emini.dynamics.Body;
import org.emini.dynamics.World;
import org.emini.math.EMath;
import org.emini.particle.ParticleEmitter;
import org.emini.shape.Shape;

/**
 * Benchmarks particles: a closed 600 px box of static walls with a few dozen dynamic boxes in it
 * and one emitter that keeps its full pool of fast particles bouncing around, at the original
 * engine's defaults (20 ticks per second). Prints the cost of a tick with the particles and of the
 * same tick without them (thread CPU time), and checks that no particle left the box.
 *
 * <p>Usage: {@code ParticleBox [particles] [seconds]} (defaults 10,000 particles, 60 s).
 */
public final class ParticleBox {
    private static final float HALF = 300f;

    private ParticleBox() {
    }

    /**
     * Runs the benchmark.
     *
     * @param args particle count and seconds, both optional
     */
    public static void main(String[] args) {
        int particles = args.length > 0 ? Integer.parseInt(args[0]) : 10_000;
        float seconds = args.length > 1 ? Float.parseFloat(args[1]) : 60f;
        World with = scene();
        World without = scene();
        ParticleEmitter e = new ParticleEmitter(particles);
        e.setCreationRate(particles, 0f);
        e.setLifetime(1000f, 0f);
        e.setSpeed(800f, 800f);
        e.setAngle(0f, EMath.TWO_PI);
        e.setEmitSegment(-100f, -250f, 100f, -250f);
        e.setElasticity(0.9f);
        with.addParticleEmitter(e);
        int ticks = Math.round(seconds / with.getTimestep());
        // Fill the pool and let the JIT settle before timing.
        for (int t = 0; t < 200; t++) {
            with.tick();
            without.tick();
        }
        // Thread CPU time, and the best of several rounds: a shared machine only ever adds time.
        ThreadMXBean clock = ManagementFactory.getThreadMXBean();
        long particleNanos = Long.MAX_VALUE;
        long bodyNanos = Long.MAX_VALUE;
        int escaped = 0;
        int rounds = 5;
        for (int r = 0; r < rounds; r++) {
            long t0 = clock.getCurrentThreadCpuTime();
            for (int t = 0; t < ticks / rounds; t++) {
                with.tick();
            }
            long t1 = clock.getCurrentThreadCpuTime();
            for (int t = 0; t < ticks / rounds; t++) {
                without.tick();
            }
            long t2 = clock.getCurrentThreadCpuTime();
            particleNanos = Math.min(particleNanos, t1 - t0);
            bodyNanos = Math.min(bodyNanos, t2 - t1);
            for (int i = 0; i < e.getParticleCount(); i++) {
                if (!(Math.abs(e.getX(i)) <= HALF && Math.abs(e.getY(i)) <= HALF)) {
                    escaped++;
                }
            }
        }
        double withMs = particleNanos / 1e6 / (ticks / rounds);
        double withoutMs = bodyNanos / 1e6 / (ticks / rounds);
        System.out.printf("particle box: %d particles (%d live), %d bodies, %d ticks of %.4f s%n",
            particles, e.getParticleCount(), with.getBodyCount(), ticks, with.getTimestep());
        System.out.printf("thread CPU time, best of %d rounds: ", rounds);
        System.out.printf("%.3f ms per tick with particles, %.3f ms without: particles cost %.3f ms per tick, %.1f ns each%n",
            withMs, withoutMs, withMs - withoutMs, (withMs - withoutMs) * 1e6 / Math.max(1, e.getParticleCount()));
        System.out.println(escaped == 0 ? "no particle left the box" : escaped + " particles left the box");
    }

    private static World scene() {
        World world = new World();
        float t = 10f;
        Shape across = Shape.createRectangle(2f * HALF + 2f * t, t);
        Shape upright = Shape.createRectangle(t, 2f * HALF + 2f * t);
        world.addBody(new Body(0f, -HALF - 0.5f * t, across, false));
        world.addBody(new Body(0f, HALF + 0.5f * t, across, false));
        world.addBody(new Body(-HALF - 0.5f * t, 0f, upright, false));
        world.addBody(new Body(HALF + 0.5f * t, 0f, upright, false));
        Shape crate = Shape.createRectangle(24f, 18f);
        Shape ball = Shape.createCircle(10f);
        for (int i = 0; i < 40; i++) {
            world.addBody(new Body(-260f + 13f * i, 200f - 30f * (i % 4), i % 2 == 0 ? crate : ball, true));
        }
        return world;
    }
}
