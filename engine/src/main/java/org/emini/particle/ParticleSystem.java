package org.emini.particle;

import org.emini.dynamics.Body;
import org.emini.dynamics.Simulation;
import org.emini.math.EMath;

/**
 * A set of particle emitters and their stepping against a world's bodies and landscape.
 *
 * <p>Every {@code World} owns one (its {@code addParticleEmitter} and related calls land here)
 * and steps it at the end of each tick, after the solver, so particles see the bodies where the
 * tick left them. An application may also own one and step it on its own schedule.
 *
 * <p>One step: each emitter ages its particles, drops the dead, moves the others ballistically and
 * emits the new ones; then, for the emitters whose particles collide, the interacting bodies and the
 * landscape segments near the particles are put in a grid and every particle's motion is tested
 * against them (see {@code ParticleCollider}); last, damping. A step allocates nothing once the arrays have grown to
 * the scene, and gives bit-identical results for the same world, emitters and seeds.
 *
 * <p>Particles move exactly on the parabola of constant gravity: x += v·dt + ½·g·dt², v += g·dt,
 * which has no integration error for the only force they feel, so a path does not depend on the
 * tick rate, and particles born part-way through a tick are placed exactly. The original moved
 * particles by Verlet steps (the same parabola at whole ticks, but with the velocity implied by
 * two positions, which a change of timestep breaks); a bounce here needs the velocity itself.
 */
public final class ParticleSystem {
    private ParticleEmitter[] emitters = new ParticleEmitter[4];
    private int emitterCount;
    final ObstacleGrid grid = new ObstacleGrid();
    private final ParticleCollider collider = new ParticleCollider(grid);

    /** Creates an empty particle system. */
    public ParticleSystem() {
    }

    /**
     * Whether an emitter is in this system.
     *
     * @param emitter the emitter, or null
     * @return true when it was added here and not removed
     */
    public boolean contains(ParticleEmitter emitter) {
        return emitter != null && emitter.system == this;
    }

    /**
     * Whether an emitter is in some system (some world).
     *
     * @param emitter the emitter
     * @return true when it belongs to a system
     */
    public static boolean isOwned(ParticleEmitter emitter) {
        return emitter.system != null;
    }

    /**
     * Adds an emitter. An emitter belongs to one particle system (one world) at a time.
     *
     * @param emitter the emitter
     * @return true when added, false when it already belongs to a particle system
     * @throws IllegalArgumentException if the emitter is null
     */
    public boolean addEmitter(ParticleEmitter emitter) {
        if (emitter == null) {
            throw new IllegalArgumentException("ParticleSystem.addEmitter: emitter must not be null");
        }
        if (emitter.system != null) {
            return false;
        }
        if (emitterCount == emitters.length) {
            ParticleEmitter[] grown = new ParticleEmitter[2 * emitterCount];
            System.arraycopy(emitters, 0, grown, 0, emitterCount);
            emitters = grown;
        }
        emitters[emitterCount++] = emitter;
        emitter.system = this;
        return true;
    }

    /**
     * Removes an emitter, with its particles (the emitter keeps them; it stops moving them).
     *
     * @param emitter the emitter
     * @return true when it was in this system
     */
    public boolean removeEmitter(ParticleEmitter emitter) {
        for (int i = 0; i < emitterCount; i++) {
            if (emitters[i] == emitter) {
                removeAt(i);
                return true;
            }
        }
        return false;
    }

    /**
     * Removes the emitters attached to a body (a world does this when the body is removed).
     *
     * @param body the body
     * @return the number of emitters removed
     */
    public int removeEmittersOf(Body body) {
        int removed = 0;
        for (int i = emitterCount - 1; i >= 0; i--) {
            if (body != null && emitters[i].getBody() == body) {
                removeAt(i);
                removed++;
            }
        }
        return removed;
    }

    private void removeAt(int i) {
        emitters[i].system = null;
        System.arraycopy(emitters, i + 1, emitters, i, emitterCount - i - 1);
        emitters[--emitterCount] = null;
    }

    /**
     * The number of emitters.
     *
     * @return the count
     */
    public int getEmitterCount() {
        return emitterCount;
    }

    /**
     * An emitter by its position in the list (insertion order).
     *
     * @param index 0 to {@link #getEmitterCount()} − 1
     * @return the emitter
     */
    public ParticleEmitter getEmitter(int index) {
        if (index < 0 || index >= emitterCount) {
            throw new IndexOutOfBoundsException("ParticleSystem.getEmitter: index " + index + " of " + emitterCount);
        }
        return emitters[index];
    }

    /**
     * The number of live particles of all emitters.
     *
     * @return the count
     */
    public int getParticleCount() {
        int n = 0;
        for (int i = 0; i < emitterCount; i++) {
            n += emitters[i].count;
        }
        return n;
    }

    /**
     * Advances every emitter and its particles by one timestep, against the world's gravity and
     * bodies as they are now.
     *
     * @param world the world whose gravity and bodies the particles feel
     * @param dt the timestep (s), &gt; 0
     */
    public void step(Simulation world, float dt) {
        if (world == null) {
            throw new IllegalArgumentException("ParticleSystem.step: world must not be null");
        }
        if (!(EMath.isFinite(dt) && dt > 0f)) {
            throw new IllegalArgumentException("ParticleSystem.step: dt must be finite and > 0, was " + dt);
        }
        float gx = world.getGravityX();
        float gy = world.getGravityY();
        float minX = Float.POSITIVE_INFINITY;
        float minY = Float.POSITIVE_INFINITY;
        float maxX = Float.NEGATIVE_INFINITY;
        float maxY = Float.NEGATIVE_INFINITY;
        for (int i = 0; i < emitterCount; i++) {
            ParticleEmitter e = emitters[i];
            e.advance(dt, gx, gy);
            if (e.canCollide() && e.count > 0) {
                minX = Math.min(minX, e.minX);
                minY = Math.min(minY, e.minY);
                maxX = Math.max(maxX, e.maxX);
                maxY = Math.max(maxY, e.maxY);
            }
        }
        if (minX <= maxX && EMath.isFinite(maxX - minX) && EMath.isFinite(maxY - minY)) {
            grid.build(world, minX, minY, maxX, maxY);
            for (int i = 0; i < emitterCount; i++) {
                ParticleEmitter e = emitters[i];
                if (e.canCollide()) {
                    collider.collide(e, dt, gx, gy);
                }
            }
        }
        for (int i = 0; i < emitterCount; i++) {
            emitters[i].damp();
        }
    }
}
