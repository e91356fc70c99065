package org.emini.harness.fuzz.world;

import org.emini.dynamics.Body;
import org.emini.dynamics.SolverStep;
import org.emini.world.World;

/** An application constraint that removes a body from the world in its {@code prepare} of one tick. */
final class RemovingConstraint extends IdleConstraint {
    private final World world;
    private final Body body;
    private final long tick;
    private boolean done;

    RemovingConstraint(World world, Body body, long tick) {
        this.world = world;
        this.body = body;
        this.tick = tick;
    }

    @Override
    public void prepare(SolverStep step) {
        if (!done && world.getTickCount() == tick) {
            done = true;
            world.removeBody(body);
        }
    }
}
