package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.InvalidShapeException;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * The supported body sizes: shapes narrower than {@link Shape#MIN_SIZE} are refused by name (a
 * 0.001 px box used to sink 0.05 px, 50 times its size, into the ground without a word), and
 * shapes of the minimum size still rest and stack at the default settings.
 */
class BodySizeTest {
    private static void refused(String value, org.junit.jupiter.api.function.Executable make) {
        InvalidShapeException e = assertThrows(InvalidShapeException.class, make);
        assertEquals(InvalidShapeException.Rule.TOO_SMALL, e.getRule(), e.getMessage());
        assertTrue(e.getMessage().contains(value) && e.getMessage().contains("MIN_SIZE"), e.getMessage());
    }

    @Test
    void shapesBelowTheMinimumSizeAreRefusedNamingTheValue() {
        refused("width 0.001", () -> Shape.createRectangle(0.001f, 20f));
        refused("height 0.2", () -> Shape.createRectangle(20f, 0.2f));
        refused("radius 0.1", () -> Shape.createCircle(0.1f));
        refused("0.0999", () -> Shape.createPolygon(0f, 0f, 10f, 0f, 10f, 0.1f));
        refused("across", () -> Shape.createRegularPolygon(0.15f, 3));
        // Exactly the minimum is allowed.
        Shape.createRectangle(Shape.MIN_SIZE, Shape.MIN_SIZE);
        Shape.createCircle(Shape.MIN_SIZE / 2f);
    }

    /** Drops a stack of three shapes of the minimum size on the ground; the largest overlap of a
     *  rested body with the one below, as a fraction of its size, after 10 s. */
    private static float stackOverlap(boolean circles) {
        float s = Shape.MIN_SIZE;
        World world = new World();
        world.addBody(new Body(0f, 10f, Shape.createRectangle(40f, 20f), false));
        Body[] stack = new Body[3];
        for (int i = 0; i < 3; i++) {
            Shape shape = circles ? Shape.createCircle(s / 2f) : Shape.createRectangle(s, s);
            stack[i] = new Body(0f, -s / 2f - 1.05f * s * i - 0.01f, shape, true);
            world.addBody(stack[i]);
        }
        for (int t = 0; t < 200; t++) {
            world.tick();
        }
        float worst = 0f;
        float below = 0f;
        for (Body b : stack) {
            assertTrue(Math.abs(b.getX()) < 0.1f * s, "drifted to x " + b.getX());
            float bottom = b.getY() + s / 2f;
            worst = Math.max(worst, (bottom - below) / s);
            below = b.getY() - s / 2f;
        }
        return worst;
    }

    @Test
    void aStackOfThreeShapesOfTheMinimumSizeRestsWithinAFifthOfTheirSize() {
        float slop = new SolverSettings().getLinearSlop();
        for (boolean circles : new boolean[] {false, true}) {
            float overlap = stackOverlap(circles);
            assertTrue(overlap <= slop / Shape.MIN_SIZE + 0.02f, (circles ? "circles" : "boxes") + " overlap " + overlap);
        }
    }
}
