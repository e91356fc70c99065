package org.emini.harness.fuzz.world;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.particle.ParticleEmitter;

/**
 * Hashes of a world's state over the exact bits of its floats: every body's pose and velocity, every
 * constraint's force, the contact count, the particles and the events reported. Equal hashes after
 * each tick are what "bit-identical" means here.
 */
public final class StateHash {
    private StateHash() {
    }

    /** The whole state, as {@code EverythingScene.hash} and more. */
    public static long of(FuzzWorld w) {
        World world = w.world();
        long h = bodies(world);
        for (int i = 0; i < world.getConstraintCount(); i++) {
            h = mix(h, world.getConstraint(i).getForce());
        }
        h = 31 * h + world.getContactCount();
        for (ParticleEmitter e : w.emitters()) {
            h = 31 * h + particles(e);
        }
        return 31 * h + (w.listener() == null ? 0 : w.listener().hash());
    }

    /** The bodies alone: position, angle, velocity and angular velocity, in world order. */
    public static long bodies(World world) {
        long h = 1125899906842597L;
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            h = mix(h, b.getX());
            h = mix(h, b.getY());
            h = mix(h, b.getAngle());
            h = mix(h, b.getVelocityX());
            h = mix(h, b.getVelocityY());
            h = mix(h, b.getAngularVelocity());
        }
        return h;
    }

    /** One emitter's live particles: position and velocity. */
    public static long particles(ParticleEmitter e) {
        long h = e.getParticleCount();
        for (int i = 0; i < e.getParticleCount(); i++) {
            h = mix(h, e.getX(i));
            h = mix(h, e.getY(i));
            h = mix(h, e.getVelocityX(i));
            h = mix(h, e.getVelocityY(i));
        }
        return h;
    }

    private static long mix(long h, float value) {
        return 31 * h + Float.floatToIntBits(value);
    }
}
