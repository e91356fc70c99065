package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * {@link SolverSettings#setAabbMargin} takes effect at the next tick of an existing world: a contact
 * exists for each pair whose fat boxes overlap, so the margin decides whether two bodies 10 px apart
 * have one.
 */
class AabbMarginTest {
    @Test
    void changingTheMarginOfAnExistingWorldChangesItsFatBoxes() {
        World world = new World();
        world.setGravity(0f, 0f);
        world.addBody(new Body(0f, 0f, Shape.createRectangle(20f, 20f), true));
        world.addBody(new Body(30f, 0f, Shape.createRectangle(20f, 20f), false));
        world.tick();
        assertEquals(0, world.getContactCount(), "margins of 2 px leave a 10 px gap");
        world.getSolverSettings().setAabbMargin(6f);
        world.tick();
        assertEquals(1, world.getContactCount(), "margins of 6 px overlap across a 10 px gap");
        world.getSolverSettings().setAabbMargin(2f);
        world.tick();
        assertEquals(0, world.getContactCount(), "back to 2 px");
    }
}
