package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * A shape far from its body's origin lands on an unfaced landscape segment as on a static floor:
 * the body's centre of mass, not its origin, decides which side of the segment it is on. With the
 * origin deciding, the origin crossed the line before the shape touched it and the segment pushed the
 * shape through (found by the world fuzzer). Faced segments keep the original's rule, the origin
 * decides (the reference worlds' events depend on it), so a one-way platform holds such a body only
 * while its origin is on the blocking side.
 */
class OffCentreLandscapeTest {
    @Test
    void anOffCentreBoxRestsOnAnUnfacedSegment() {
        World world = new World();
        world.getLandscape().addSegment(-200f, 0f, 200f, 0f);
        Body box = new Body(0f, -60f, Shape.createPolygon(-10f, -30f, 10f, -30f, 10f, -10f, -10f, -10f), true);
        world.addBody(box);
        Body multi = new Body(80f, -60f, Shape.createMultiShape(Shape.createPolygon(-10f, -50f, 10f, -50f, 10f, -30f,
            -10f, -30f), Shape.createCircle(4f)), true);
        world.addBody(multi);
        for (int t = 0; t < 60; t++) {
            world.tick();
        }
        // The box's bottom is 10 px above its origin: it rests with the origin at y ≈ 10.
        assertTrue(Math.abs(box.getY() - 10f) < 0.5f, "box origin at " + box.getY());
        assertTrue(multi.getY() < 31f, "multi-shape origin at " + multi.getY());
    }
}
