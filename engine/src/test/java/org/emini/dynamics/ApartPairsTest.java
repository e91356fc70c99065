package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * The narrowphase decides a pair it left apart from a flat copy ({@link ApartPairs}), without its
 * contact object; the copy must follow every change the object would have seen. Pairs 1 px apart
 * (their fat boxes overlap, so each has a contact without points), nothing moving.
 */
class ApartPairsTest {
    private static World world() {
        World world = new World();
        world.setGravity(0f, 0f);
        return world;
    }

    /** A box of its own shape at (x, 0), static or not. */
    private static Body box(World world, float x, boolean dynamic) {
        Body b = new Body(x, 0f, Shape.createRectangle(20f, 20f), dynamic);
        world.addBody(b);
        return b;
    }

    private static void tick(World world, int ticks) {
        for (int i = 0; i < ticks; i++) {
            world.tick();
        }
    }

    @Test
    void anApartPairFollowsItsShapesFrictionAndElasticity() {
        World world = world();
        Body a = box(world, 0f, true);
        Body b = box(world, 21f, true);
        b.getShape().setElasticity(0.8f);
        tick(world, 5);
        assertEquals(1, world.getContactCount());
        Contact contact = world.getContact(0);
        assertEquals(0, contact.getPointCount());
        // One change a tick (each away from the default): either alone must reach the contact.
        b.getShape().setFriction(0.75f);
        tick(world, 1);
        assertSame(contact, world.getContact(0));
        assertEquals(a.getShape().getFriction() * 0.75f, contact.getFriction());
        a.getShape().setElasticity(0.5f);
        tick(world, 1);
        assertEquals(0.5f * 0.8f, contact.getElasticity());
    }

    @Test
    void anApartPairWhoseFilterNowRefusesItEndsAtOnce() {
        World world = world();
        Body a = box(world, 0f, true);
        Body b = box(world, 21f, true);
        tick(world, 5);
        assertEquals(1, world.getContactCount());
        // The same group, negative: the two never collide.
        a.setGroupIndex(-1);
        b.setGroupIndex(-1);
        tick(world, 1);
        assertEquals(0, world.getContactCount());
    }

    @Test
    void aContactMovedIntoAnEndedOnesPlaceKeepsItsOwnCopy() {
        World world = world();
        Body a1 = box(world, 0f, false);
        Body b1 = box(world, 21f, true);
        Body a2 = box(world, 200f, false);
        Body b2 = box(world, 221f, true);
        tick(world, 5);
        assertEquals(2, world.getContactCount());
        Contact first = world.getContact(0);
        Contact second = first.getBodyA() == a2 || first.getBodyB() == a2 ? first : world.getContact(1);
        // The first pair ends; the contact array's last contact takes its index.
        b1.setPosition(0f, 500f);
        tick(world, 1);
        assertEquals(1, world.getContactCount());
        assertEquals(0, a1.getContactCount());
        // Nothing of the second pair moved: its contact lives on, apart, then touches when pushed.
        tick(world, 3);
        assertEquals(1, a2.getContactCount(), "the second pair lost its contact");
        assertSame(second, world.getContact(0));
        b2.setPosition(219f, 0f);
        tick(world, 1);
        assertSame(second, world.getContact(0));
        assertTrue(second.getPointCount() > 0, "the pushed pair touches");
    }
}
