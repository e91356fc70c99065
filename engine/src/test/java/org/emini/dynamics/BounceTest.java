package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** A ball dropped with elasticity e rebounds to e² of its drop height. */
class BounceTest {
    @ParameterizedTest
    @CsvSource({"0.9, 20", "0.7, 20", "0.5, 20", "0.8, 60", "0.3, 60"})
    void reboundHeightIsElasticitySquared(float e, int ticksPerSecond) {
        World world = new World();
        world.setTicksPerSecond(ticksPerSecond);
        Body ground = Scenes.ground(world, 0f, 400f);
        ground.getShape().setElasticity(1f);
        Shape ballShape = Shape.createCircle(10f);
        ballShape.setElasticity(e);
        float dropHeight = 200f;
        Body ball = new Body(0f, -10f - dropHeight, ballShape, true);
        world.addBody(ball);
        // Fall, bounce, and track the apex after the first bounce.
        boolean bounced = false;
        float apex = Float.MAX_VALUE;
        for (int t = 0; t < ticksPerSecond * 6; t++) {
            float vyBefore = ball.getVelocityY();
            world.tick();
            if (!bounced && vyBefore > 0f && ball.getVelocityY() < 0f) {
                bounced = true;
            }
            if (bounced) {
                apex = Math.min(apex, ball.getY());
                if (ball.getVelocityY() > 0f) {
                    break;
                }
            }
        }
        // The apex is sampled at ticks; the tolerance allows for the sampling error of ½·g·dt².
        float rebound = -10f - apex;
        float expected = e * e * dropHeight;
        assertEquals(expected, rebound, 0.05f * expected + 100f / ticksPerSecond / ticksPerSecond,
            "rebound of a ball with e=" + e);
    }
}
