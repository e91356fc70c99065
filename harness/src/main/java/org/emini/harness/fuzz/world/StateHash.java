package org.emini.harness.fuzz.world;

import org.emini.particle.ParticleEmitter;
import org.emini.world.World;

/**
 * A fuzzed world's whole state as one hash: {@link org.emini.harness.run.StateHash} of its world, over the
 * emitters the recipe made (in the recipe's order, kept after their body is removed from the world), and
 * the events its listener heard. Equal hashes after each tick are what "bit-identical" means for twin runs.
 */
public final class StateHash {
    private StateHash() {
    }

    /** The whole state, as {@code EverythingScene.hash} and more. */
    public static long of(FuzzWorld w) {
        World world = w.world();
        long h = org.emini.harness.run.StateHash.dynamics(world);
        for (ParticleEmitter e : w.emitters()) {
            h = 31 * h + org.emini.harness.run.StateHash.particles(e);
        }
        return 31 * h + (w.listener() == null ? 0 : w.listener().hash());
    }
}
