package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * A contact kept across ticks is found by its handle while it lasts and never after, even when its
 * pooled object serves a new pair; reading an ended contact fails loudly.
 */
class ContactHandleTest {
    @Test
    void aHandleFindsItsContactUntilItEndsAndNeverAnother() {
        World world = new World();
        Body ground = new Body(0f, 10f, Shape.createRectangle(400f, 20f), false);
        world.addBody(ground);
        Body box = new Body(0f, -11f, Shape.createRectangle(20f, 20f), true);
        world.addBody(box);
        for (int i = 0; i < 20; i++) {
            world.tick();
        }
        assertEquals(1, world.getContactCount());
        Contact contact = world.getContact(0);
        long handle = contact.getHandle();
        for (int i = 0; i < 20; i++) {
            world.tick();
            assertSame(contact, world.findContact(handle), "the resting contact lasts");
        }

        world.removeBody(box);
        assertNull(world.findContact(handle));
        IllegalStateException ended = assertThrows(IllegalStateException.class, contact::getPointCount);
        assertTrue(ended.getMessage().startsWith("Contact.getPointCount: the contact has ended"), ended.getMessage());

        // A new pair takes the pooled object: the old handle still names nothing.
        Body other = new Body(50f, -11f, Shape.createRectangle(20f, 20f), true);
        world.addBody(other);
        world.tick();
        assertEquals(1, world.getContactCount());
        Contact fresh = world.getContact(0);
        assertSame(contact, fresh, "the pool gives the object back (why a raw reference is not enough)");
        assertNull(world.findContact(handle));
        assertNotNull(world.findContact(fresh.getHandle()));
        assertTrue(fresh.getHandle() != handle);
        assertNull(world.findContact(-1L));
        assertNull(world.findContact(Long.MAX_VALUE));
    }
}
