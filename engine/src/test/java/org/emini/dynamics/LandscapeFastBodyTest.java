package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.MultiShape;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Fast bodies do not pass through a landscape segment (a line with no thickness at all), from any
 * of 64 start offsets spread over one tick's travel and at any angle; a faced segment still lets a
 * fast body coming from its open side through.
 */
class LandscapeFastBodyTest {
    private static final int OFFSETS = 64;

    private static Shape shape(String kind) {
        switch (kind) {
            case "box":
                return Shape.createRectangle(40f, 4f);
            case "ball":
                return Shape.createCircle(2.5f);
            default:
                return new MultiShape(Shape.createRectangle(40f, 4f), Shape.createRectangle(4f, 40f));
        }
    }

    /** Counts the offsets from which the body's centre ever got beyond the segment y = 0. */
    private static int crossings(String kind, float speed, float spin, int face) {
        int crossed = 0;
        float travel = speed / 20f;
        for (int k = 0; k < OFFSETS; k++) {
            World world = new World();
            world.setGravity(0f, 0f);
            world.getLandscape().addSegment(-3000f, 0f, 3000f, 0f, face);
            Body b = new Body(k * 3.7f, -100f - travel * (3f + k / (float) OFFSETS), shape(kind), true);
            b.setAngle(k * 0.37f);
            b.setVelocity(0f, speed);
            b.setAngularVelocity(spin);
            world.addBody(b);
            boolean beyond = false;
            for (int t = 0; t < 12; t++) {
                world.tick();
                beyond |= b.getY() > 0f;
            }
            if (beyond) {
                crossed++;
            }
        }
        return crossed;
    }

    @ParameterizedTest(name = "{0} at {1} px/s spinning {2} rad/s, face {3}")
    @CsvSource({"box, 10000, 0, 0", "box, 10000, 30, 0", "ball, 20000, 0, 0", "multi, 10000, 20, 0", "box, 10000, 0, 1"})
    void fastBodiesNeverCrossALandscapeSegment(String kind, float speed, float spin, int face) {
        assertEquals(0, crossings(kind, speed, spin, face), "offsets from which the body crossed");
    }

    /** Face 2 blocks bodies below the segment (y > 0), so a body from above passes at any speed. */
    @ParameterizedTest(name = "{0}")
    @CsvSource({"box", "ball"})
    void aFastBodyFromTheOpenSidePassesAFacedSegment(String kind) {
        World world = new World();
        world.setGravity(0f, 0f);
        world.getLandscape().addSegment(-3000f, 0f, 3000f, 0f, Landscape.FACE_RIGHT);
        Body b = new Body(0f, -1000f, shape(kind), true);
        b.setVelocity(0f, 10000f);
        world.addBody(b);
        for (int t = 0; t < 4; t++) {
            world.tick();
        }
        assertTrue(b.getY() > 900f, "passed: y " + b.getY());
        assertEquals(10000f, b.getVelocityY(), 1e-2f);
    }
}
