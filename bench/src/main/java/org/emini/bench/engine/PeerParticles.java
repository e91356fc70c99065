package org.emini.bench.engine;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Particles for the engines that have none (dyn4j, Box2D), made the way a game developer makes them:
 * each particle is a small circle body ({@link PeerScene#PARTICLE_RADIUS}, fixed rotation, no
 * friction, the emitter's elasticity as restitution) whose collision filter lets it meet the scene's
 * bodies but not other particles. Before each step the bodies of particles past their lifetime are
 * destroyed and the tick's new particles created at random points of the emit segment, with the
 * emitter's random speed, direction and lifetime (uniform deviations, as Emini's emitters draw them,
 * from a generator of their own: the same distributions, not the same particles).
 *
 * <p>Unlike Emini's particles, these are rigid bodies: the engine integrates them and solves their
 * contacts with the solver's iterations; a particle is born at the start of a tick, not spread over it.
 *
 * @param <B> the engine's body type
 */
final class PeerParticles<B> {
    /** What the engine does for the particles. */
    interface Physics<B> {
        /** Creates a particle body at (x, y) m with velocity (vx, vy) m/s. */
        B create(PeerScene.PeerEmitter e, double x, double y, double vx, double vy);

        /** Destroys a particle body. */
        void destroy(B body);

        /** x of a body (m). */
        double x(B body);

        /** y of a body (m, up). */
        double y(B body);
    }

    private final List<PeerScene.PeerEmitter> emitters;
    private final Physics<B> physics;
    private final SplittableRandom[] random;
    private final double[] owed;
    private final List<List<B>> bodies = new ArrayList<>();
    private final double[][] deaths;
    private double time;

    PeerParticles(List<PeerScene.PeerEmitter> emitters, Physics<B> physics) {
        this.emitters = emitters;
        this.physics = physics;
        random = new SplittableRandom[emitters.size()];
        owed = new double[emitters.size()];
        deaths = new double[emitters.size()][];
        for (int i = 0; i < emitters.size(); i++) {
            random[i] = new SplittableRandom(emitters.get(i).seed);
            bodies.add(new ArrayList<>(emitters.get(i).maxCount));
            deaths[i] = new double[emitters.get(i).maxCount];
        }
    }

    /** Whether the scene has emitters. */
    boolean any() {
        return !emitters.isEmpty();
    }

    /** Before a step of dt: the dead go, the tick's newborn come. */
    void beforeStep(double dt) {
        for (int k = 0; k < emitters.size(); k++) {
            PeerScene.PeerEmitter e = emitters.get(k);
            List<B> live = bodies.get(k);
            double[] death = deaths[k];
            for (int i = live.size() - 1; i >= 0; i--) {
                if (death[i] <= time) {
                    physics.destroy(live.get(i));
                    int last = live.size() - 1;
                    live.set(i, live.get(last));
                    death[i] = death[last];
                    live.remove(last);
                }
            }
            SplittableRandom r = random[k];
            owed[k] += Math.max(0, e.rate + (r.nextDouble() - 0.5) * e.rateSpread) * dt;
            int n = (int) owed[k];
            owed[k] -= n;
            for (int j = 0; j < n && live.size() < e.maxCount; j++) {
                double u = r.nextDouble();
                double x = e.x1 + u * (e.x2 - e.x1), y = e.y1 + u * (e.y2 - e.y1);
                double a = e.angle + (r.nextDouble() - 0.5) * e.angleSpread;
                double v = e.speed + (r.nextDouble() - 0.5) * e.speedSpread;
                double life = e.lifetime + (r.nextDouble() - 0.5) * e.lifetimeSpread;
                death[live.size()] = time + life;
                live.add(physics.create(e, x, y, v * Math.cos(a), v * Math.sin(a)));
            }
        }
        time += dt;
    }

    /** Live particles. */
    int count() {
        int n = 0;
        for (List<B> l : bodies) {
            n += l.size();
        }
        return n;
    }

    /** x, y (px, y down) of every live particle to out[2 i], out[2 i + 1]. */
    void positions(double[] out) {
        int i = 0;
        for (List<B> l : bodies) {
            for (B b : l) {
                out[2 * i] = physics.x(b) * PeerScene.PX_PER_M;
                out[2 * i + 1] = -physics.y(b) * PeerScene.PX_PER_M;
                i++;
            }
        }
    }
}
