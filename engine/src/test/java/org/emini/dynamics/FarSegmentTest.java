package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.shape.MultiShape;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * A landscape segment far from everything changes nothing, bit for bit: a body's landscape contacts
 * are made in segment order, not in the order the segment index's tree reports them (a segment at
 * 10⁶ px rebuilt the tree and reordered the solve; world fuzzer finding, seed 2026).
 */
class FarSegmentTest {
    private static float[] run(boolean far) {
        World world = new World();
        world.setConstraintIterations(1);
        world.setGravity(33.875f, 141.375f);
        Landscape l = world.getLandscape();
        l.setFriction(0.21875f);
        l.addSegment(-261.375f, -31.625f, -156.8125f, 9.5f);
        l.addSegment(-156.8125f, 9.5f, -52.25f, -34.125f);
        l.addSegment(156.8125f, -19.1875f, 261.375f, -31.9375f, Landscape.FACE_LEFT);
        l.addSegment(261.375f, -31.9375f, 365.9375f, 8.25f);
        l.addSegment(20.125f, -198f, 103.1875f, -181.375f, Landscape.FACE_RIGHT);
        if (far) {
            l.addSegment(1e6f, 1e6f, 1e6f + 100f, 1e6f);
        }
        Shape a = Shape.createPolygon(-27.46875f, -10.34375f, -1.65625f, -10.34375f, -1.65625f, 6.09375f, -27.46875f,
            6.09375f);
        Shape c = Shape.createPolygon(-17.28125f, -22.71875f, -10.34375f, -22.71875f, -10.34375f, -4.65625f, -17.28125f,
            -4.65625f);
        a.setMass(0.75f);
        c.setMass(1.296875f);
        MultiShape m = Shape.createMultiShape(a, c).centred();
        m.setFriction(0.609375f);
        Body b = new Body(262.5f, -104.8125f, m, true);
        b.setBullet(true);
        world.addBody(b);
        for (int i = 0; i < 40; i++) {
            world.tick();
        }
        return new float[] {b.getX(), b.getY(), b.getAngle(), b.getVelocityX(), b.getVelocityY()};
    }

    @Test
    void aSegmentFarAwayChangesNothing() {
        float[] near = run(false);
        float[] far = run(true);
        for (int i = 0; i < near.length; i++) {
            assertEquals(Float.floatToIntBits(near[i]), Float.floatToIntBits(far[i]), "component " + i);
        }
    }
}
