package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * Ten stacked boxes dropped together onto the ground at the manual's defaults (20 ticks/s, 10
 * iterations), elasticity 0: the column must land and stay, whatever the round-off. Gauss–Seidel
 * carries the landing up the column in about n² relax passes; with 30 impact relax passes a substep
 * the column's top two boxes left it at 20.6 px/s when gravity was two parts per million weaker and
 * at 3.7 px/s as written, so a check of the scene as written passed by luck (found by the harness's
 * nudged runs). The check runs at several such gravities for that reason.
 */
class ColumnDropTest {
    /** The fastest rise of any box from 1.5 s (0.09 s after the 141 px/s landing) to 4 s. */
    private static float fastestRise(float gravityY, int impactPasses, float sweep) {
        World world = new World();
        world.setTicksPerSecond(20f);
        world.setConstraintIterations(10);
        world.setGravity(0f, gravityY);
        world.getSolverSettings().setImpactRelaxPasses(impactPasses);
        world.getSolverSettings().setSpeculativeSweep(sweep);
        world.addBody(new Body(0f, 20f, Shape.createRectangle(400f, 40f), false));
        Shape box = Shape.createRectangle(20f, 20f);
        Body[] column = new Body[10];
        for (int i = 0; i < column.length; i++) {
            column[i] = new Body(0f, -110f - 20f * i, box, true);
            world.addBody(column[i]);
        }
        float rise = 0f;
        for (int tick = 1; tick <= 80; tick++) {
            world.tick();
            if (tick >= 30) {
                for (Body b : column) {
                    rise = Math.max(rise, -b.getVelocityY());
                }
            }
        }
        return rise;
    }

    @Test
    void aColumnLandsWithoutReboundAtGravitiesAPartPerMillionApart() {
        int passes = new SolverSettings().getImpactRelaxPasses();
        for (float g : new float[] {100f, 99.9998f, 100.0002f, 99.999f, 100.001f}) {
            float rise = fastestRise(g, passes, 1f);
            // 10% of the 141 px/s landing speed, the library scene's bound (overlap/column-drop-20hz).
            assertTrue(rise < 14.1f, "gravity " + g + ": a box rose at " + rise + " px/s after landing with elasticity 0");
        }
    }

    @Test
    void withTenImpactPassesTheColumnRebounds() {
        // What the passes are for: the test above cannot pass without them (25-35% of the landing speed).
        float rise = fastestRise(100f, 10, 1f);
        System.out.printf("column dropped with 10 impact relax passes: fastest rise %.1f px/s%n", rise);
        assertTrue(rise > 14.1f, "with 10 impact relax passes a box rose at only " + rise + " px/s");
    }

    @Test
    void withoutTheSpeculativeSweepTheColumnRebounds() {
        // The sweep stops the bottom box at the ground in the tick it lands; without it the box sinks
        // several pixels into the ground, and the push back out launches the boxes above it.
        float rise = fastestRise(100f, new SolverSettings().getImpactRelaxPasses(), 0f);
        System.out.printf("column dropped without the speculative sweep: fastest rise %.1f px/s%n", rise);
        assertTrue(rise > 14.1f, "without the speculative sweep a box rose at only " + rise + " px/s");
    }
}
