package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A faced landscape segment stops bodies from its blocking side and lets bodies from its open side
 * pass, as the original engine does (original-engine-facts §9): face 1 blocks the left-hand side of
 * start → end on a y-down screen, where (end − start) × (p − start) &lt; 0; face 2 the other side;
 * face 0 both.
 */
class LandscapeFacingTest {
    private static Shape shape(String kind) {
        return kind.equals("box") ? Shape.createRectangle(20f, 20f) : Shape.createCircle(10f);
    }

    /** The table of §9: a segment from (−100, 0) to (100, 0), gravity towards it, 60 ticks. */
    @ParameterizedTest(name = "face {0}, {1} from {2}: stopped {3}")
    @CsvSource({
        "0, box, above, true", "0, box, below, true", "0, circle, above, true", "0, circle, below, true",
        "1, box, above, true", "1, box, below, false", "1, circle, above, true", "1, circle, below, false",
        "2, box, above, false", "2, box, below, true", "2, circle, above, false", "2, circle, below, true"})
    void facedSegmentStopsBodiesAsInTheOriginalsTable(int face, String kind, String from, boolean stopped) {
        World world = new World();
        world.getLandscape().addSegment(-100f, 0f, 100f, 0f, face);
        float side = from.equals("above") ? -1f : 1f;
        world.setGravity(0f, -side * 100f);
        Body body = new Body(0f, side * 50f, shape(kind), true);
        world.addBody(body);
        for (int t = 0; t < 60; t++) {
            world.tick();
        }
        if (stopped) {
            assertEquals(side * 10f, body.getY(), 0.2f, "rests against the segment on its side");
            assertEquals(0f, body.getVelocityY(), 1f);
        } else {
            assertTrue(body.getY() * side < -100f, "passed through, ended at y " + body.getY());
        }
    }

    /**
     * The general rule at any direction: the body starts 60 px from the segment's middle on one
     * side and falls towards it. A segment given with end x ≤ start x is stored swapped with its
     * face flipped, so the rule holds for the direction as given.
     */
    @ParameterizedTest(name = "{0}° face {1} side {2}")
    @CsvSource({
        "0, 1, -1", "0, 1, 1", "0, 2, -1", "0, 2, 1",
        "30, 1, -1", "30, 1, 1", "30, 2, -1", "30, 2, 1",
        "90, 1, -1", "90, 1, 1", "90, 2, -1", "90, 2, 1",
        "150, 1, -1", "150, 1, 1", "150, 2, -1", "150, 2, 1",
        "180, 1, -1", "180, 1, 1", "180, 2, -1", "180, 2, 1",
        "250, 1, -1", "250, 1, 1", "250, 2, -1", "250, 2, 1",
        "270, 0, -1", "270, 0, 1", "315, 0, -1", "315, 0, 1"})
    void faceBlocksTheSideGivenByTheCrossProductAtAnyDirection(float degrees, int face, int side) {
        for (String kind : new String[] {"box", "circle"}) {
            double a = Math.toRadians(degrees);
            float ux = (float) Math.cos(a);
            float uy = (float) Math.sin(a);
            // Left normal: (end − start) × (p − start) has the sign of (p − start)·(−uy, ux).
            float nx = -uy;
            float ny = ux;
            World world = new World();
            world.getLandscape().addSegment(-100f * ux, -100f * uy, 100f * ux, 100f * uy, face);
            world.setGravity(-side * 100f * nx, -side * 100f * ny);
            Body body = new Body(side * 60f * nx, side * 60f * ny, shape(kind), true);
            body.setAngle((float) a);
            world.addBody(body);
            for (int t = 0; t < 60; t++) {
                world.tick();
            }
            boolean blocks = face == Landscape.FACE_NONE || (face == Landscape.FACE_LEFT) == (side < 0);
            float distance = side * (body.getX() * nx + body.getY() * ny);
            if (blocks) {
                assertEquals(10f, distance, 0.3f, kind + " rests against the segment on its side");
            } else {
                assertTrue(distance < -100f, kind + " passed through, ended " + distance + " px beyond");
            }
        }
    }

    @ParameterizedTest(name = "face {0}")
    @CsvSource({"1, 2", "2, 1", "0, 0"})
    void segmentGivenRightToLeftIsStoredLeftToRightWithTheFaceFlipped(int face, int stored) {
        Landscape l = new Landscape();
        l.addSegment(100f, 5f, -100f, -5f, face);
        assertEquals(-100f, l.getStartX(0));
        assertEquals(-5f, l.getStartY(0));
        assertEquals(100f, l.getEndX(0));
        assertEquals(5f, l.getEndY(0));
        assertEquals(stored, l.getFace(0));
    }

    /**
     * A body already overlapping a faced segment from its open side is never pushed back: it keeps
     * its speed and completes its passage (once its centre has crossed, the push-out only helps it
     * along).
     */
    @ParameterizedTest(name = "{0}")
    @CsvSource({"box", "circle"})
    void bodyOverlappingFromTheOpenSideIsNeverPushedBack(String kind) {
        World world = new World();
        world.getLandscape().addSegment(-100f, 0f, 100f, 0f, Landscape.FACE_LEFT);
        // Below the segment (its open side) and overlapping it by 8 px, moving up slowly.
        world.setGravity(0f, 0f);
        Body body = new Body(0f, 2f, shape(kind), true);
        body.setVelocity(0f, -20f);
        world.addBody(body);
        for (int t = 0; t < 40; t++) {
            world.tick();
            assertEquals(-20f, body.getVelocityY(), 1e-3f, "no push at tick " + t);
        }
        assertTrue(body.getY() <= 2f - 40f + 1e-3f, "not held back: ended at y " + body.getY());
    }
}
