package org.emini.harness.run;

import java.util.Locale;
import org.emini.dynamics.Body;
import org.emini.particle.ParticleEmitter;
import org.emini.world.World;

/**
 * Hashes of a world's state over the exact bits of its floats: every body's pose and velocity, every
 * constraint's force, the contact count and the particles. Equal hashes after each tick are what
 * "bit-identical" means here: {@code run} chains them over a scene's ticks ({@link SceneResult#stateHash}),
 * so that two runs of the library (one thread against two, a build before an optimisation against one
 * after) can be proved the same with {@code diff --same-state}; the world fuzzer compares its twin runs
 * with the same hash.
 */
public final class StateHash {
    private StateHash() {
    }

    /** The whole state of a world: {@link #dynamics} and the particles of its emitters, in world order. */
    public static long world(World world) {
        long h = dynamics(world);
        for (int i = 0; i < world.getParticleEmitterCount(); i++) {
            h = 31 * h + particles(world.getParticleEmitter(i));
        }
        return h;
    }

    /**
     * The state without particles: the bodies ({@link #bodies}), every constraint's force and the contact
     * count. For callers that keep their own list of emitters (the fuzzer hashes those it made, in its order).
     */
    public static long dynamics(World world) {
        long h = bodies(world);
        for (int i = 0; i < world.getConstraintCount(); i++) {
            h = mix(h, world.getConstraint(i).getForce());
        }
        return 31 * h + world.getContactCount();
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

    /** A hash as results.json writes it: 16 lower-case hex digits. */
    public static String hex(long hash) {
        return String.format(Locale.ROOT, "%016x", hash);
    }

    private static long mix(long h, float value) {
        return 31 * h + Float.floatToIntBits(value);
    }
}
