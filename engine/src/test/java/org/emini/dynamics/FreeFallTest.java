package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Free flight matches the closed form of the integrator: symplectic Euler over substeps of
 * h = dt / iterations gives v = g·t exactly and y = y0 + v0·t + ½·g·t² + ½·g·h·t.
 */
class FreeFallTest {
    @ParameterizedTest
    @CsvSource({"20, 10", "60, 4", "20, 1", "30, 7"})
    void fallMatchesSymplecticEulerClosedForm(int ticksPerSecond, int iterations) {
        World world = new World();
        world.setTicksPerSecond(ticksPerSecond);
        world.setConstraintIterations(iterations);
        Body ball = new Body(10f, -1000f, Shape.createCircle(5f), true);
        ball.setVelocity(30f, -80f);
        world.addBody(ball);
        int ticks = 2 * ticksPerSecond;
        for (int i = 0; i < ticks; i++) {
            world.tick();
        }
        double dt = 1.0 / ticksPerSecond;
        double t = ticks * dt;
        double h = dt / iterations;
        double g = 100.0;
        assertEquals(-80.0 + g * t, ball.getVelocityY(), 1e-3);
        assertEquals(30.0, ball.getVelocityX(), 1e-4);
        double y = -1000.0 - 80.0 * t + 0.5 * g * t * t + 0.5 * g * h * t;
        assertEquals(y, ball.getY(), 0.05);
        assertEquals(10.0 + 30.0 * t, ball.getX(), 1e-2);
    }

    @Test
    void gravityPointsAnywhereAndCanBeChangedBetweenTicks() {
        World world = new World();
        world.setGravity(-50f, 0f);
        Body b = new Body(0f, 0f, Shape.createRectangle(10f, 10f), true);
        world.addBody(b);
        Scenes.run(world, 1f);
        assertEquals(-50.0, b.getVelocityX(), 1e-3);
        assertEquals(0.0, b.getVelocityY(), 0.0);
        world.setGravity(0f, 0f);
        float x = b.getX();
        Scenes.run(world, 1f);
        assertEquals(-50.0, b.getVelocityX(), 1e-3);
        assertEquals(x - 50.0, b.getX(), 1e-2);
    }

    @Test
    void bodiesNotAffectedByGravityFloat() {
        World world = new World();
        Body b = new Body(0f, 0f, Shape.createCircle(3f), true);
        b.setGravityAffected(false);
        world.addBody(b);
        Scenes.run(world, 2f);
        assertEquals(0.0, b.getY(), 0.0);
    }

    @Test
    void appliedForceAndTorqueActForOneTick() {
        World world = new World();
        world.setGravity(0f, 0f);
        Shape shape = Shape.createRectangle(20f, 20f);
        Body b = new Body(0f, 0f, shape, true);
        world.addBody(b);
        b.applyForce(40f, 0f);
        b.applyTorque(shape.getInertia() * 2f);
        world.tick();
        assertEquals(40f * world.getTimestep() / shape.getMass(), b.getVelocityX(), 1e-5);
        assertEquals(2f * world.getTimestep(), b.getAngularVelocity(), 1e-5);
        world.tick();
        assertEquals(40f * world.getTimestep() / shape.getMass(), b.getVelocityX(), 1e-5);
    }

    @Test
    void dampingRemovesTheGivenFractionPerTick() {
        World world = new World();
        world.setGravity(0f, 0f);
        world.setDampingLateral(0.05f);
        world.setDampingRotational(0.1f);
        Body b = new Body(0f, 0f, Shape.createRectangle(20f, 20f), true);
        b.setVelocity(100f, 0f);
        b.setAngularVelocity(1f);
        world.addBody(b);
        for (int i = 0; i < 10; i++) {
            world.tick();
        }
        assertEquals(100.0 * Math.pow(0.95, 10), b.getVelocityX(), 1e-3);
        assertEquals(Math.pow(0.9, 10), b.getAngularVelocity(), 1e-5);
    }

    @Test
    void freeRotationKeepsAngularVelocityAndAdvancesTheAngle() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body rod = new Body(0f, 0f, Shape.createRectangle(200f, 4f), true);
        rod.setAngularVelocity(50f);
        world.addBody(rod);
        Scenes.run(world, 1f);
        assertEquals(50.0, rod.getAngularVelocity(), 1e-4);
        assertEquals(50.0, rod.getAngle(), 1e-3);
        assertEquals(Math.cos(50.0), rod.getCos(), 2e-3);
        assertEquals(Math.sin(50.0), rod.getSin(), 2e-3);
    }
}
