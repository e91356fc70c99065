package org.emini.harness.fuzz.world;

import java.util.List;
import java.util.Map;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.harness.run.StateHash;
import org.emini.world.World;
import org.emini.particle.ParticleEmitter;

/**
 * An engine world built from a recipe, with its bodies in recipe order and by id, its emitters and
 * its listener.
 *
 * @param recipe what it was built from
 * @param world the engine world
 * @param bodies the bodies, in the recipe's order (a removed body stays here, out of the world)
 * @param byId the bodies by recipe id
 * @param constraints the joints, springs and motors by "joint:ID", "spring:ID", "motor:ID"
 * @param emitters the emitters, in the recipe's order
 * @param listener the listener, or null when the recipe sets none
 */
public record FuzzWorld(Recipe recipe, World world, Body[] bodies, Map<Integer, Body> byId,
                        Map<String, Constraint> constraints, List<ParticleEmitter> emitters, FuzzListener listener) {
    /** Runs one tick. */
    public void tick() {
        world.tick();
    }

    /** Events reported so far (0 without a listener). */
    public long eventCount() {
        return listener == null ? 0 : listener.count();
    }

    /** How reports name a body: "body ID" with its recipe id and kind. */
    public String name(Body b) {
        for (int i = 0; i < bodies.length; i++) {
            if (bodies[i] == b) {
                return "body " + recipe.bodies.get(i).id + (b.isDynamic() ? "" : " (static)");
            }
        }
        return String.valueOf(b);
    }

    /**
     * The whole state as one hash: {@link StateHash#dynamics} of the world, the emitters the recipe made
     * (in the recipe's order, kept after their body is removed from the world) and the events the listener
     * heard. Equal hashes after each tick are what "bit-identical" means for twin runs.
     */
    public long stateHash() {
        long h = StateHash.dynamics(world);
        for (ParticleEmitter e : emitters) {
            h = 31 * h + StateHash.particles(e);
        }
        return 31 * h + (listener == null ? 0 : listener.hash());
    }

    /** Whether the body is still in the world. */
    public boolean inWorld(Body b) {
        return b.getWorld() == world;
    }
}
