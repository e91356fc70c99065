package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * World.disableCollision keeps exactly one pair from colliding: the two boxes pass through each other,
 * while a third box still lands on both (a shared layer bit would have stopped that too).
 */
class DisableCollisionTest {
    @Test
    void aDisabledPairPassesThroughEachOtherAndNothingElseChanges() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body left = new Body(0f, 0f, Shape.createRectangle(20f, 20f), true);
        Body right = new Body(40f, 0f, Shape.createRectangle(20f, 20f), true);
        Body third = new Body(20f, -40f, Shape.createRectangle(60f, 10f), true);
        world.addBody(left);
        world.addBody(right);
        world.addBody(third);
        world.disableCollision(left, right);
        assertTrue(world.isCollisionDisabled(right, left));
        left.setVelocity(100f, 0f);
        right.setVelocity(-100f, 0f);
        third.setVelocity(0f, 100f);
        for (int t = 0; t < 8; t++) {
            world.tick();
        }
        assertTrue(left.getX() > right.getX(), "the boxes passed through each other: " + left.getX() + " / " + right.getX());
        assertTrue(third.getVelocityY() < 90f, "the third box hit them: " + third.getVelocityY());
        world.enableCollision(left, right);
        assertFalse(world.isCollisionDisabled(left, right));
        assertThrows(IllegalArgumentException.class, () -> world.disableCollision(left, left));
    }

    @Test
    void reEnablingMakesTheOverlappingPairPushApart() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body a = new Body(0f, 0f, Shape.createRectangle(20f, 20f), true);
        Body b = new Body(10f, 0f, Shape.createRectangle(20f, 20f), true);
        world.addBody(a);
        world.addBody(b);
        world.disableCollision(a, b);
        for (int t = 0; t < 5; t++) {
            world.tick();
        }
        assertEquals(10f, b.getX() - a.getX(), 1e-4f);
        world.enableCollision(a, b);
        for (int t = 0; t < 40; t++) {
            world.tick();
        }
        assertTrue(b.getX() - a.getX() > 19.5f, "pushed apart: " + (b.getX() - a.getX()));
    }
}
