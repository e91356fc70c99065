package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A box on an incline of angle θ with friction μ (the product of the two shapes' factors) sticks
 * when tan θ &lt; μ and otherwise slides with a = g(sin θ − μ cos θ).
 */
class InclineTest {
    private static final float G = 100f;

    /** Places a 20 px box at rest on a static slope; returns {box, slope}. */
    private static Body[] slope(World world, float degrees, float mu) {
        float theta = (float) Math.toRadians(degrees);
        Shape ground = Shape.createRectangle(4000f, 20f);
        ground.setFriction(1f);
        Body slope = new Body(0f, 0f, ground, false);
        slope.setAngle(theta);
        world.addBody(slope);
        Shape boxShape = Shape.createRectangle(20f, 20f);
        boxShape.setFriction(mu);
        // Box centre 20 px above the slope's centre line, along the slope's normal (sin θ, −cos θ).
        float lx = -300f;
        float ly = -20f;
        float c = (float) Math.cos(theta);
        float s = (float) Math.sin(theta);
        Body box = new Body(c * lx - s * ly, s * lx + c * ly, boxShape, true);
        box.setAngle(theta);
        world.addBody(box);
        return new Body[] {box, slope};
    }

    private static float along(Body b, float theta) {
        return (float) (b.getX() * Math.cos(theta) + b.getY() * Math.sin(theta));
    }

    @ParameterizedTest
    @CsvSource({"20, 0.5, 20", "30, 0.7, 20", "10, 0.25, 60", "40, 0.9, 20"})
    void boxSticksWhenTanThetaBelowMu(float degrees, float mu, int tps) {
        World world = new World();
        world.setTicksPerSecond(tps);
        Body[] scene = slope(world, degrees, mu);
        float theta = (float) Math.toRadians(degrees);
        Scenes.run(world, 0.5f);
        float start = along(scene[0], theta);
        Scenes.run(world, 5f);
        float moved = along(scene[0], theta) - start;
        assertTrue(Math.abs(moved) < 0.5f, "box on a " + degrees + "° slope with μ=" + mu + " crept " + moved + " px");
        assertEquals(theta, scene[0].getAngle(), 0.01f);
    }

    @ParameterizedTest
    @CsvSource({"30, 0.2, 20", "45, 0.5, 20", "30, 0, 20", "35, 0.4, 60", "25, 0.3, 60"})
    void boxSlidesWithClosedFormAcceleration(float degrees, float mu, int tps) {
        World world = new World();
        world.setTicksPerSecond(tps);
        Body[] scene = slope(world, degrees, mu);
        float theta = (float) Math.toRadians(degrees);
        Scenes.run(world, 0.5f);
        float v0 = (float) (scene[0].getVelocityX() * Math.cos(theta) + scene[0].getVelocityY() * Math.sin(theta));
        Scenes.run(world, 2f);
        float v1 = (float) (scene[0].getVelocityX() * Math.cos(theta) + scene[0].getVelocityY() * Math.sin(theta));
        double expected = G * (Math.sin(theta) - mu * Math.cos(theta));
        double measured = (v1 - v0) / 2.0;
        assertEquals(expected, measured, 0.05 * expected, "acceleration on " + degrees + "° with μ=" + mu);
        assertEquals(theta, scene[0].getAngle(), 0.01f, "the box slides without tipping");
    }
}
