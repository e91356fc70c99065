package org.emini.examples;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.math.EMath;
import org.emini.particle.ParticleEmitter;
import org.emini.shape.Shape;

/**
 * Benchmarks particles: a closed 600 px box of static walls with 40 dynamic crates and balls in it
 * and one emitter that fills its pool with fast particles (400 to 1,200 px/s, elasticity 0.9) that
 * bounce around and settle, at the original engine's defaults (20 ticks per second). Prints the
 * thread CPU time of a tick without particles, with them, and with particles that collide with
 * nothing, and checks that no particle left the box.
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
        // The same scene three times: bodies only, with bouncing particles, with particles that
        // collide with nothing (emission and motion alone).
        World[] worlds = {scene(), scene(), scene()};
        ParticleEmitter bouncing = emitter(particles);
        ParticleEmitter flying = emitter(particles);
        flying.setCanCollide(false);
        worlds[1].addParticleEmitter(bouncing);
        worlds[2].addParticleEmitter(flying);
        int ticks = Math.round(seconds / worlds[0].getTimestep());
        // Fill the pools and let the JIT settle before timing.
        for (int t = 0; t < 200; t++) {
            for (World w : worlds) {
                w.tick();
            }
        }
        // Thread CPU time, and the best of several rounds: a shared machine only ever adds time.
        ThreadMXBean clock = ManagementFactory.getThreadMXBean();
        long[] best = {Long.MAX_VALUE, Long.MAX_VALUE, Long.MAX_VALUE};
        int escaped = 0;
        int rounds = 5;
        for (int r = 0; r < rounds; r++) {
            for (int k = 0; k < worlds.length; k++) {
                long t0 = clock.getCurrentThreadCpuTime();
                for (int t = 0; t < ticks / rounds; t++) {
                    worlds[k].tick();
                }
                best[k] = Math.min(best[k], clock.getCurrentThreadCpuTime() - t0);
            }
            for (int i = 0; i < bouncing.getParticleCount(); i++) {
                if (!(Math.abs(bouncing.getX(i)) <= HALF && Math.abs(bouncing.getY(i)) <= HALF)) {
                    escaped++;
                }
            }
        }
        int moving = 0;
        for (int i = 0; i < bouncing.getParticleCount(); i++) {
            float vx = bouncing.getVelocityX(i);
            float vy = bouncing.getVelocityY(i);
            if (vx * vx + vy * vy > 50f * 50f) {
                moving++;
            }
        }
        double[] ms = new double[3];
        for (int k = 0; k < 3; k++) {
            ms[k] = best[k] / 1e6 / (ticks / rounds);
        }
        int n = Math.max(1, bouncing.getParticleCount());
        System.out.printf("particle box: %d particles (%d live, %d faster than 50 px/s at the end), %d bodies, %d ticks of %.4f s%n",
            particles, bouncing.getParticleCount(), moving, worlds[0].getBodyCount(), ticks, worlds[0].getTimestep());
        System.out.printf("thread CPU time per tick, best of %d rounds: bodies alone %.3f ms; with bouncing particles %.3f ms"
            + " (particles %.3f ms, %.0f ns each); with particles that collide with nothing %.3f ms (%.0f ns each)%n",
            rounds, ms[0], ms[1], ms[1] - ms[0], (ms[1] - ms[0]) * 1e6 / n, ms[2], (ms[2] - ms[0]) * 1e6 / n);
        System.out.println(escaped == 0 ? "no particle left the box" : escaped + " particles left the box");
    }

    private static ParticleEmitter emitter(int particles) {
        ParticleEmitter e = new ParticleEmitter(particles);
        e.setCreationRate(particles, 0f);
        e.setLifetime(1000f, 0f);
        e.setSpeed(800f, 800f);
        e.setAngle(0f, EMath.TWO_PI);
        e.setEmitSegment(-100f, -250f, 100f, -250f);
        e.setElasticity(0.9f);
        return e;
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
