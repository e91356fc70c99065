package org.emini.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.emini.math.EMath;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * {@link ShapeCaster} where exactness is hardest: two corners meeting head-on, where the contact is
 * at the end of a face on both sides and float rounding may put it a hair past every face's end.
 */
class ShapeCasterTest {
    private final ShapeCaster caster = new ShapeCaster();

    /**
     * Two squares turned so that a corner of each points at the other along a random direction, far
     * from the origin; the moving one travels along the line through both corners. They must meet,
     * corner on corner, after the gap between the corners, whatever the rounding.
     */
    @Test
    void cornersMeetingHeadOnAreNeverLost() {
        Polygon square = Shape.createRectangle(20f, 20f);
        float half = (float) (10 * Math.sqrt(2));
        Random r = new Random(3);
        for (int i = 0; i < 20000; i++) {
            double dir = 2 * Math.PI * r.nextDouble();
            double ux = Math.cos(dir);
            double uy = Math.sin(dir);
            double far = 1000 * r.nextDouble();
            double bx = far * Math.cos(7 * dir) + ux * 60;
            double by = far * Math.sin(7 * dir) + uy * 60;
            double ax = bx - ux * 120;
            double ay = by - uy * 120;
            // A corner of a square turned by dir + 45° points along dir.
            float turnA = (float) (dir + Math.PI / 4);
            float turnB = (float) (dir + Math.PI + Math.PI / 4);
            float dx = (float) (ux * 200);
            float dy = (float) (uy * 200);
            boolean hit = caster.cast(square, (float) ax, (float) ay, EMath.cos(turnA), EMath.sin(turnA), dx, dy, square,
                (float) bx, (float) by, EMath.cos(turnB), EMath.sin(turnB));
            assertTrue(hit, "corner " + i + " at angle " + dir + " lost");
            assertEquals((120 - 2 * half) / 200, caster.t, 1e-5, "corner " + i);
        }
    }
}
