package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Automatic fast-body treatment against dynamic bodies, no bullet flag: a small ball fired at a free
 * thin plank hits it in the tick it arrives and pushes it, conserving momentum. A ball set moving
 * fast inside its broadphase box used to get no pair with the plank and pass straight through it.
 */
class FastDynamicHitTest {
    @ParameterizedTest(name = "plank {0} px thick, ball at {1} px/s, {2} ticks/s")
    @CsvSource({"2, 3200, 20", "10, 3200, 20", "2, 10000, 20", "2, 3200, 60", "10, 30000, 60"})
    void aFastBallHitsAFreeThinPlankInsteadOfPassingThroughIt(float thickness, float speed, float rate) {
        World world = new World();
        world.setTicksPerSecond(rate);
        world.setGravity(0f, 0f);
        Body ball = new Body(0f, 0f, Shape.createCircle(2f), true);
        Body plank = new Body(100f + 0.5f * thickness, 0f, Shape.createRectangle(thickness, 60f), true);
        world.addBody(ball);
        world.addBody(plank);
        ball.setVelocity(speed, 0f);
        for (int t = 0; t < 10; t++) {
            world.tick();
            assertTrue(ball.getX() < plank.getX(), "tick " + t + ": ball at " + ball.getX() + ", plank at " + plank.getX());
        }
        float momentum = ball.getVelocityX() * ball.getMass() + plank.getVelocityX() * plank.getMass();
        assertEquals(speed, momentum, 0.01f * speed, "momentum");
        assertTrue(plank.getVelocityX() > 0.4f * speed, "the plank was pushed: " + plank.getVelocityX());
    }
}
