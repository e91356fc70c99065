package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.dynamics.Body;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A chassis on a wheel held still, sprung at f along a vertical axis through its centre: it
 * bounces with period 1/f (ω = 2πf for the chassis mass m, stiffness k = m·ω²) about its sag
 * g/ω² below the spring's rest.
 */
class WheelSuspensionTest {
    private static final float HERTZ = 2f;

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void chassisBouncesWithTheSpringPeriodAboutItsSag(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        Body chassis = new Body(0f, 0f, Shape.createRectangle(80f, 20f), true);
        world.addBody(chassis);
        Body wheel = new Body(0f, 0f, Shape.createCircle(12f), false);
        world.addBody(wheel);
        WheelJoint joint = WheelJoint.atWorldPoint(chassis, wheel, 0f, 0f, 0f, 1f);
        joint.setCollisionLayer(1);
        joint.setSpring(HERTZ, 0f);
        world.addConstraint(joint);

        double omega = 2 * Math.PI * HERTZ;
        double sag = world.getGravityY() / (omega * omega);
        double period = Oscillation.period(world, () -> chassis.getY(), sag, 6);
        // With damping the chassis settles at the sag, where the spring holds m·g.
        joint.setSpring(HERTZ, 1f);
        Rigs.run(world, (int) Math.round(3 * ticksPerSecond));
        double weight = chassis.getMass() * world.getGravityY();
        System.out.printf("wheel %.0f ticks/s: period %.5f s vs %.5f, sag %.4f px vs g/ω² %.4f, spring force %.3f vs m·g %.3f%n",
            ticksPerSecond, period, 1.0 / HERTZ, chassis.getY(), sag, joint.getSpringForce(), weight);
        assertEquals(1.0 / HERTZ, period, 0.005 / HERTZ);
        assertEquals(sag, chassis.getY(), 0.005 * sag);
        assertEquals(-sag, joint.getTranslation(), 0.005 * sag);
        assertEquals(weight, joint.getSpringForce(), 0.001 * weight);
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void motorTurnsTheWheelAtItsSpeed(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        world.setGravity(0f, 0f);
        Body chassis = new Body(0f, 0f, Shape.createRectangle(80f, 20f), false);
        world.addBody(chassis);
        Body wheel = new Body(0f, 30f, Shape.createCircle(12f), true);
        world.addBody(wheel);
        WheelJoint joint = WheelJoint.atWorldPoint(chassis, wheel, 0f, 30f, 0f, 1f);
        joint.setSpring(4f, 0.7f);
        float torque = wheel.getInertia() * 2f;
        joint.setMotor(6f, torque);
        world.addConstraint(joint);
        // Angular acceleration T/I = 2 rad/s² until 6 rad/s.
        Rigs.run(world, (int) Math.round(ticksPerSecond));
        assertEquals(2.0, wheel.getAngularVelocity(), 1e-3);
        assertEquals(torque, joint.getMotorTorque(), 1e-3 * torque);
        Rigs.run(world, (int) Math.round(3 * ticksPerSecond));
        assertEquals(6.0, wheel.getAngularVelocity(), 1e-3);
        assertEquals(30.0, wheel.getY(), 0.01);
        assertEquals(0.0, wheel.getX(), 0.01);
    }
}
