package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * Reusing a contact's points while its bodies barely move ({@link SolverSettings#getManifoldReuseDistance()})
 * must not change what the bodies do beyond the pile's own creep, and must never touch a pair that is
 * moving: the same world with reuse on and off.
 */
class ManifoldReuseTest {
    private static World world(float reuse) {
        World world = new World();
        world.setTicksPerSecond(60);
        world.getSolverSettings().setManifoldReuseDistance(reuse);
        return world;
    }

    @Test
    void aSettledPyramidStandsAsWhenEveryContactIsCollidedEveryTick() {
        World reused = world(0.1f);
        World collided = world(0f);
        Body[] a = Scenes.pyramid(reused, 10, 20f);
        Body[] b = Scenes.pyramid(collided, 10, 20f);
        for (int t = 0; t < 600; t++) {
            reused.tick();
            collided.tick();
        }
        for (int i = 0; i < a.length; i++) {
            // Both piles creep by up to 0.1 px in 10 s (SleepTest); reuse stays within that.
            assertEquals(b[i].getX(), a[i].getX(), 0.1f, "x of box " + i);
            assertEquals(b[i].getY(), a[i].getY(), 0.1f, "y of box " + i);
            assertEquals(b[i].getAngle(), a[i].getAngle(), 1e-3f, "angle of box " + i);
        }
        // The reused points describe the same overlap as fresh ones: the same deepest point per contact.
        assertEquals(deepest(collided), deepest(reused), 0.01f);
    }

    @Test
    void aBoxHeldByFrictionOnATiltedSlopeStaysWhereItWouldWithoutReuse() {
        // The slope's normal is not a world axis: reused points must keep the box on it, not in it.
        float[] end = new float[4];
        for (int k = 0; k < 2; k++) {
            World world = world(k == 0 ? 0.1f : 0f);
            world.setGravity(0f, 100f);
            Shape ground = Shape.createRectangle(4000f, 20f);
            ground.setFriction(1f);
            Body slope = new Body(0f, 0f, ground, false);
            slope.setAngle(0.3f);
            world.addBody(slope);
            Shape boxShape = Shape.createRectangle(20f, 20f);
            boxShape.setFriction(1f);
            Body box = new Body(-300f * 0.9553365f + 20f * 0.29552022f, -300f * 0.29552022f - 20f * 0.9553365f,
                boxShape, true);
            box.setAngle(0.3f);
            world.addBody(box);
            for (int t = 0; t < 300; t++) {
                world.tick();
            }
            end[2 * k] = box.getX();
            end[2 * k + 1] = box.getY();
            // tan 0.3 < μ = 1: it sticks.
            assertTrue(Math.abs(box.getVelocityX()) + Math.abs(box.getVelocityY()) < 0.5f, "at rest");
        }
        assertEquals(end[2], end[0], 0.05f);
        assertEquals(end[3], end[1], 0.05f);
    }

    @Test
    void reusedPointsTurnWithAPairThatTurnsAsOne() {
        // Two boxes, B resting on A, found touching; then the pair turns 0.3 rad about A's centre as
        // one rigid piece. Their points are reused (nothing moved relative to the pair), and must
        // turn with it: the normal, the points, the unchanged separations.
        Body a = new Body(0f, 0f, Shape.createRectangle(60f, 10f), true);
        Body b = new Body(0f, -14.9f, Shape.createRectangle(20f, 20f), true);
        Contact c = new Contact();
        c.bodyA = a;
        c.bodyB = b;
        c.pointCount = 2;
        c.normalX = 0f;
        c.normalY = -1f;
        c.pointX0 = -10f;
        c.pointY0 = -5.05f;
        c.pointX1 = 10f;
        c.pointY1 = -5.05f;
        c.separation0 = -0.1f;
        c.separation1 = -0.1f;
        ManifoldReuse.remember(c, a, b, true, 0f, 0.1f);
        float angle = 0.3f;
        float cos = (float) Math.cos(angle);
        float sin = (float) Math.sin(angle);
        a.setAngle(angle);
        b.setAngle(angle);
        b.setPosition(-sin * -14.9f, cos * -14.9f);
        assertTrue(ManifoldReuse.reuse(c, a, b, 0f, 0.1f));
        assertEquals(sin, c.normalX, 1e-6f);
        assertEquals(-cos, c.normalY, 1e-6f);
        assertEquals(-0.1f, c.separation0, 1e-5f);
        assertEquals(-0.1f, c.separation1, 1e-5f);
        assertEquals(cos * -10f + sin * 5.05f, c.pointX0, 1e-4f);
        assertEquals(sin * -10f - cos * 5.05f, c.pointY0, 1e-4f);
        // Moved apart by more than the tolerance, the pair is collided again.
        b.setPosition(b.getX(), b.getY() - 0.2f);
        assertTrue(!ManifoldReuse.reuse(c, a, b, 0f, 0.1f));
    }

    @Test
    void aSlidingBoxIsCollidedEveryTickBitForBit() {
        // Sliding at 120 px/s covers 2 px a tick, far beyond the 0.1 px reuse distance: no contact of
        // it may be reused, so both worlds are the same bit for bit until it slows down.
        Body[] boxes = new Body[2];
        World[] worlds = new World[2];
        for (int k = 0; k < 2; k++) {
            worlds[k] = world(k == 0 ? 0.1f : 0f);
            Shape ground = Shape.createRectangle(2000f, 20f);
            ground.setFriction(1f);
            worlds[k].addBody(new Body(0f, 10f, ground, false));
            boxes[k] = new Body(0f, -10f, Shape.createRectangle(20f, 20f), true);
            boxes[k].setVelocity(120f, 0f);
            worlds[k].addBody(boxes[k]);
        }
        int compared = 0;
        while (boxes[1].getVelocityX() > 30f && compared < 600) {
            worlds[0].tick();
            worlds[1].tick();
            assertEquals(Float.floatToIntBits(boxes[1].getX()), Float.floatToIntBits(boxes[0].getX()));
            assertEquals(Float.floatToIntBits(boxes[1].getY()), Float.floatToIntBits(boxes[0].getY()));
            assertEquals(Float.floatToIntBits(boxes[1].getAngle()), Float.floatToIntBits(boxes[0].getAngle()));
            compared++;
        }
        assertTrue(compared > 20 && compared < 600, "ticks compared " + compared);
    }

    private static float deepest(World world) {
        float min = 0f;
        for (int i = 0; i < world.getContactCount(); i++) {
            Contact c = world.getContact(i);
            for (int p = 0; p < c.getPointCount(); p++) {
                min = Math.min(min, c.getSeparation(p));
            }
        }
        return min;
    }
}
