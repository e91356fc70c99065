package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Fast bodies do not pass through thin walls. Each case is run from many start offsets spread over
 * one tick's travel, so the wall is met at every phase of the step; a crossing is a body whose
 * centre ends on the far side of the wall.
 */
class FastBodyTest {
    private static final int OFFSETS = 64;

    /** Counts the start offsets from which the body ended beyond the wall at x = 0 (wall 2 px thick). */
    private static int crossings(Shape bodyShape, float speed, float angle, float spin, int ticksPerSecond, float wallThickness) {
        int crossed = 0;
        float travel = speed / ticksPerSecond;
        for (int k = 0; k < OFFSETS; k++) {
            World world = new World();
            world.setGravity(0f, 0f);
            world.setTicksPerSecond(ticksPerSecond);
            world.addBody(new Body(wallThickness * 0.5f, 0f, Shape.createRectangle(wallThickness, 400f), false));
            float start = -40f - travel * (3f + k / (float) OFFSETS);
            Body b = new Body(start, 0f, bodyShape, true);
            b.setAngle(angle);
            b.setVelocity(speed, 0f);
            b.setAngularVelocity(spin);
            world.addBody(b);
            for (int t = 0; t < 10; t++) {
                world.tick();
            }
            if (b.getX() > wallThickness * 0.5f) {
                crossed++;
            }
        }
        return crossed;
    }

    @ParameterizedTest
    @CsvSource({"1000, 20", "5000, 20", "20000, 20", "20000, 60", "50000, 20"})
    void smallBallDoesNotTunnelThroughAThinWall(float speed, int tps) {
        assertEquals(0, crossings(Shape.createCircle(2.5f), speed, 0f, 0f, tps, 2f),
            "5 px ball at " + speed + " px/s, " + tps + " ticks/s");
    }

    @ParameterizedTest
    @CsvSource({"10000, 20, 0", "10000, 20, 0.7", "10000, 60, 1.57", "3000, 20, 0.3"})
    void thinBoxDoesNotTunnelThroughAThinWall(float speed, int tps, float angle) {
        assertEquals(0, crossings(Shape.createRectangle(40f, 4f), speed, angle, 0f, tps, 2f),
            "40x4 box at " + speed + " px/s, angle " + angle);
    }

    private static float maxCornerX(Body rod) {
        float c = rod.getCos();
        float s = rod.getSin();
        float half = 100f * Math.abs(c) + 2f * Math.abs(s);
        return rod.getX() + half;
    }

    @ParameterizedTest
    @CsvSource({"50, 20, 60", "50, 60, 60", "30, 20, 90", "50, 20, 95"})
    void spinningRodDoesNotPassThroughAWall(float spin, int tps, float distance) {
        int crossed = 0;
        for (int k = 0; k < OFFSETS; k++) {
            World world = new World();
            world.setGravity(0f, 0f);
            world.setTicksPerSecond(tps);
            Body wall = new Body(1f, 0f, Shape.createRectangle(2f, 600f), false);
            world.addBody(wall);
            Body rod = new Body(-distance, 0f, Shape.createRectangle(200f, 4f), true);
            // Start clear of the wall, at angles spread over the whole range where it is clear.
            float clear = (float) Math.acos((distance - 4f) / 100f);
            rod.setAngle(clear + (float) (Math.PI - 2 * clear) * k / OFFSETS);
            rod.setAngularVelocity(spin);
            world.addBody(rod);
            for (int t = 0; t < 2 * tps; t++) {
                world.tick();
                // A crossing: a corner of the rod beyond the wall's far face (x = 2).
                if (maxCornerX(rod) > 2.5f) {
                    crossed++;
                    break;
                }
            }
        }
        assertEquals(0, crossed, "rod spinning at " + spin + " rad/s, centre " + distance + " px from the wall");
    }
}
