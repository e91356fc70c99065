package org.emini.world;

import org.emini.dynamics.Body;
import org.emini.dynamics.CopyMapping;

/**
 * A force from outside the simulated system (wind, buoyancy, magnets, a player's thrust), applied
 * every tick. Gravity is the built-in one.
 *
 * <p>At the start of each {@link World#tick()}, before anything moves, the world calls
 * {@link #applyForce} of every registered force in the order they were added. An implementation
 * reads the bodies ({@link World#getBodyCount()}, {@link World#getBody(int)}) and calls
 * {@link Body#applyForce}, {@link Body#applyForceAt}, {@link Body#applyAcceleration} or
 * {@link Body#applyTorque}; the solver then integrates those forces over the tick together with
 * gravity. It must not add or remove bodies, and should not allocate, so ticks stay garbage-free.
 */
public interface ExternalForce {
    /**
     * Applies this force for the coming tick.
     *
     * @param world the world being ticked
     * @param timestep the length of the tick (s)
     */
    void applyForce(World world, float timestep);

    /**
     * The force for a copied world (the original's {@code copy(mapping)}). The default shares this
     * object, right for a force that keeps no bodies of its own (it reads them from the world it
     * is given); a force that holds bodies returns a copy on {@code mapping.body(...)} of them.
     *
     * @param mapping the copies of the world's bodies and constraints
     * @return the force to add to the copy
     */
    default ExternalForce copy(CopyMapping mapping) {
        return this;
    }
}
