package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A disc that rolls without slipping: its centre moves at ω r, with r the disc's radius, also while it
 * settles into the contact's slop (the contact point midway in the overlap tied it to ω (r − d/2)).
 */
class RollingDiscTest {
    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(ints = {20, 60})
    void aDiscRollingOnFlatGroundKeepsItsSpeedAndRollsAtOmegaR(int rate) {
        World world = new World();
        world.setTicksPerSecond(rate);
        world.addBody(new Body(0f, 10f, rough(Shape.createRectangle(100000f, 20f)), false));
        Body body = new Body(0f, -10f, rough(Shape.createCircle(10f)), true);
        world.addBody(body);
        body.setVelocity(66f, 0f);
        body.setAngularVelocity(6.6f);
        for (int t = 0; t < 2 * rate; t++) {
            world.tick();
        }
        // Before: 65.985 px/s and ω r 66.029 after 2 s at 20 ticks/s.
        assertEquals(66f, body.getVelocityX(), 1e-3f, "speed");
        assertEquals(body.getVelocityX(), 10f * body.getAngularVelocity(), 1e-3f, "rolls at ω r");
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(ints = {20, 60})
    void aDiscRollsDownASlopeWithTwoThirdsOfGSinTheta(int rate) {
        World world = new World();
        world.setTicksPerSecond(rate);
        Body plank = new Body(0f, 0f, rough(Shape.createRectangle(600f, 20f)), false);
        plank.setAngle((float) Math.toRadians(30));
        world.addBody(plank);
        Body body = new Body(10f, -17.3205f, rough(Shape.createCircle(10f)), true);
        world.addBody(body);
        double c = Math.cos(Math.toRadians(30));
        double s = Math.sin(Math.toRadians(30));
        double a = 2.0 / 3.0 * 100.0 * s;
        double worst = 0;
        for (int t = 1; t <= 2 * rate; t++) {
            world.tick();
            double along = body.getVelocityX() * c + body.getVelocityY() * s;
            worst = Math.max(worst, Math.abs(along - a * t / rate));
        }
        // Before: 0.019 px/s at 20 ticks/s, growing as the disc settled into the slop.
        assertEquals(0.0, worst, 0.002, "speed along the slope against a t");
    }

    /** Friction 1: enough to roll without slipping on a 30° slope (1 ≥ tan 30° / 3). */
    private static Shape rough(Shape shape) {
        shape.setFriction(1f);
        return shape;
    }
}
