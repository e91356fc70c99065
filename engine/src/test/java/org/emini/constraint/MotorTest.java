package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * Motors reach their target when their force suffices, at the rate force/mass, and not when it
 * does not; the original's modes (axis left free, orthogonal, relative) and per-axis limits.
 */
class MotorTest {
    private static Body disc(World world, float mass) {
        Shape s = Shape.createCircle(10f);
        s.setMass(mass);
        Body b = new Body(0f, 0f, s, true);
        world.addBody(b);
        return b;
    }

    private static World weightless() {
        World world = Rigs.world(20f, 10);
        world.setGravity(0f, 0f);
        return world;
    }

    @Test
    void linearMotorAcceleratesAtForceOverMassThenHoldsTheTarget() {
        World world = weightless();
        Body body = disc(world, 2f);
        Motor motor = new Motor(body, 50f, 0f, 40f);
        world.addConstraint(motor);
        // a = F/m = 20 px/s²: v(t) = 20·t until 50 px/s at t = 2.5 s.
        for (int t = 1; t <= 100; t++) {
            world.tick();
            float expected = Math.min(50f, 20f * t * world.getTimestep());
            assertEquals(expected, body.getVelocityX(), 1e-3f, "tick " + t);
            assertEquals(0f, body.getVelocityY(), 0f);
            if (t < 50) {
                assertEquals(40f, motor.getForce(), 1e-3f);
            }
        }
        // At the target in free space it needs no force.
        assertEquals(0f, motor.getForce(), 1e-3f);
    }

    @Test
    void motorTooWeakToLiftTheBodyDoesNotReachItsTarget() {
        World world = Rigs.world(20f, 10);
        Body weak = disc(world, 1f);
        Body strong = disc(world, 1f);
        strong.setPosition(100f, 0f);
        float g = world.getGravityY();
        // Upwards at 30 px/s; the weight is m·g = 100.
        world.addConstraint(new Motor(weak, 0f, -30f, 60f));
        world.addConstraint(new Motor(strong, 0f, -30f, 150f));
        Rigs.run(world, 40);
        float t = 40 * world.getTimestep();
        System.out.printf("lifting motor: force 60 < m·g: v = %.3f px/s (closed form (g − F/m)·t = %.3f); force 150: v = %.3f%n",
            weak.getVelocityY(), (g - 60f) * t, strong.getVelocityY());
        assertEquals((g - 60f) * t, weak.getVelocityY(), 1e-2f);
        assertEquals(-30f, strong.getVelocityY(), 1e-3f);
    }

    @Test
    void motorWeakerThanFrictionLeavesABoxStanding() {
        World world = Rigs.world(20f, 10);
        world.addBody(new Body(0f, 10f, Shape.createRectangle(1000f, 20f), false));
        Shape box = Shape.createRectangle(20f, 20f);
        box.setFriction(1f);
        Body stuck = new Body(-100f, -10f, box, true);
        Body moving = new Body(100f, -10f, box, true);
        world.addBody(stuck);
        world.addBody(moving);
        // Friction 1 × 0.25 (the ground's): sliding needs 0.25·m·g = 25.
        world.addConstraint(new Motor(stuck, 40f, 0f, 20f));
        world.addConstraint(new Motor(moving, 40f, 0f, 35f));
        Rigs.run(world, 100);
        assertEquals(-100f, stuck.getX(), 0.1f);
        assertEquals(0f, stuck.getVelocityX(), 0.01f);
        assertEquals(40f, moving.getVelocityX(), 0.01f);
    }

    @Test
    void axisWithZeroTargetIsLeftToGravity() {
        World world = Rigs.world(20f, 10);
        Body body = disc(world, 1f);
        world.addConstraint(new Motor(body, 30f, 0f, 1000f));
        Rigs.run(world, 20);
        assertEquals(30f, body.getVelocityX(), 1e-3f);
        // Free fall along y: v = g·t.
        assertEquals(world.getGravityY() * 20 * world.getTimestep(), body.getVelocityY(), 1e-2f);
    }

    @Test
    void linearMotorDrivesOnlyAlongItsDirection() {
        World world = weightless();
        Body body = disc(world, 1f);
        body.setVelocity(10f, -10f);
        // Target (30, 30): speed 30√2 along the diagonal; the perpendicular (10, −10) stays.
        world.addConstraint(new Motor(body, 30f, 30f, 1e4f));
        Rigs.run(world, 5);
        assertEquals(40f, body.getVelocityX(), 1e-3f);
        assertEquals(20f, body.getVelocityY(), 1e-3f);
    }

    @Test
    void orthogonalMotorBrakesThePerpendicularMotion() {
        World world = weightless();
        Body body = disc(world, 1f);
        body.setVelocity(0f, 40f);
        Motor motor = new Motor(body, 50f, 0f, 1e4f);
        motor.setOrthogonal(true);
        world.addConstraint(motor);
        world.tick();
        assertEquals(50f, body.getVelocityX(), 1e-3f);
        assertEquals(0f, body.getVelocityY(), 1e-3f);
    }

    @Test
    void orthogonalMotorLimitsEachAxisSeparately() {
        World world = weightless();
        Body body = disc(world, 1f);
        Motor motor = new Motor(body, 100f, 100f, 10f);
        motor.setOrthogonal(true);
        world.addConstraint(motor);
        Rigs.run(world, 20);
        // Each axis gets the full 10: a = 10 px/s² on x and on y, not 10/√2.
        assertEquals(10f, body.getVelocityX(), 1e-3f);
        assertEquals(10f, body.getVelocityY(), 1e-3f);
        assertEquals(10f * (float) Math.sqrt(2), motor.getForce(), 1e-3f);
    }

    @Test
    void relativeMotorTurnsItsTargetWithTheBody() {
        World world = weightless();
        Body body = disc(world, 1f);
        body.setAngle((float) (Math.PI / 2));
        Motor motor = new Motor(body, 30f, 0f, 1e4f);
        motor.setRelative(true);
        motor.setOrthogonal(true);
        world.addConstraint(motor);
        world.tick();
        // The body's x axis points down the screen at 90°.
        assertEquals(0f, body.getVelocityX(), 1e-3f);
        assertEquals(30f, body.getVelocityY(), 1e-3f);
        // Spinning, it drives along its current heading: a circle of radius v/ω.
        body.setAngularVelocity(1f);
        Rigs.run(world, 20);
        float heading = body.getAngle();
        assertEquals(30f * (float) Math.cos(heading), body.getVelocityX(), 0.5f);
        assertEquals(30f * (float) Math.sin(heading), body.getVelocityY(), 0.5f);
    }

    @Test
    void rotationalMotorSpinsUpAtTorqueOverInertiaThenHoldsItsTarget() {
        World world = weightless();
        Body body = disc(world, 2f);
        float inertia = body.getInertia();
        float torque = 0.5f * inertia;
        Motor motor = new Motor(body, 3f, torque);
        world.addConstraint(motor);
        assertTrue(motor.isRotational());
        for (int t = 1; t <= 200; t++) {
            world.tick();
            float expected = Math.min(3f, 0.5f * t * world.getTimestep());
            assertEquals(expected, body.getAngularVelocity(), 1e-4f, "tick " + t);
        }
        // A load: a torque against it that the motor can hold, then one it cannot.
        body.applyTorque(-0.4f * inertia);
        world.tick();
        assertEquals(3f, body.getAngularVelocity(), 1e-4f);
        assertEquals(0.4f * inertia, motor.getForce(), 1e-3f * inertia);
        body.applyTorque(-0.7f * inertia);
        world.tick();
        assertEquals(3f - 0.2f * world.getTimestep(), body.getAngularVelocity(), 1e-4f);
    }

    @Test
    void motorOnAStaticBodyDoesNothing() {
        World world = Rigs.world(20f, 10);
        Body wall = Rigs.anchor(world, 0f, 0f);
        Motor motor = new Motor(wall, 50f, 50f, 1e4f);
        world.addConstraint(motor);
        world.addConstraint(new Motor(wall, 5f, 1e4f));
        Rigs.run(world, 10);
        assertEquals(0f, wall.getX(), 0f);
        assertEquals(0f, wall.getVelocityX(), 0f);
        assertEquals(0f, wall.getAngle(), 0f);
        assertEquals(0f, motor.getForce(), 0f);
    }

    @Test
    void switchingTheTargetSwitchesTheMode() {
        World world = weightless();
        Body body = disc(world, 1f);
        Motor motor = new Motor(body, 2f, 1e4f);
        world.addConstraint(motor);
        world.tick();
        assertEquals(2f, body.getAngularVelocity(), 1e-4f);
        motor.setTargetVelocity(0f, 25f);
        assertTrue(!motor.isRotational());
        world.tick();
        assertEquals(25f, body.getVelocityY(), 1e-3f);
        assertEquals(2f, body.getAngularVelocity(), 1e-4f);
    }
}
