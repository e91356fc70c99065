package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A bob on a hinge released 1.2 rad from the vertical swings down and is stopped by the upper
 * angle limit 0.6 rad before the vertical: it never passes the limit, and at rest the limit holds
 * the gravity torque m·g·L·sin(0.6).
 */
class RevoluteLimitTest {
    private static final float ARM = 100f;
    private static final double START = 1.2;
    private static final float LIMIT = 0.6f;

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void pendulumStopsAtTheLimitAndHoldsTheGravityTorque(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        Body pivot = Rigs.anchor(world, 0f, 0f);
        Body bob = new Body((float) (ARM * Math.sin(START)), (float) (ARM * Math.cos(START)), Shape.createCircle(5f), true);
        world.addBody(bob);
        RevoluteJoint hinge = RevoluteJoint.atWorldPoint(pivot, bob, 0f, 0f);
        hinge.setLimits(-LIMIT, LIMIT);
        world.addConstraint(hinge);

        double worst = 0.0;
        for (int i = 0; i < 4 * ticksPerSecond; i++) {
            world.tick();
            worst = Math.max(worst, hinge.getJointAngle());
        }
        // Joint angle = 1.2 − (angle from the vertical): the limit stops the bob 0.6 rad from it.
        double fromVertical = Math.atan2(bob.getX(), bob.getY());
        double expected = bob.getMass() * world.getGravityY() * ARM * Math.sin(START - LIMIT);
        System.out.printf("revolute limit %.0f ticks/s: worst angle %.5f rad (limit %.2f), at rest %.5f rad from the"
            + " vertical, limit torque %.2f vs m·g·L·sin θ %.2f%n", ticksPerSecond, worst, LIMIT, fromVertical,
            hinge.getTorque(), expected);
        assertTrue(worst <= LIMIT + 0.01, "passed the limit: " + worst);
        assertEquals(START - LIMIT, fromVertical, 0.01);
        // The limit pushes B (the bob) back, against growing angles.
        assertEquals(-expected, hinge.getTorque(), 0.01 * expected);
        assertEquals(bob.getMass() * world.getGravityY(), hinge.getForce(), 0.01 * bob.getMass() * world.getGravityY());
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void motorSpinsTwoFreeDiscsApartWithEqualAndOppositeTorques(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        world.setGravity(0f, 0f);
        Body a = new Body(0f, 0f, Shape.createCircle(20f), true);
        Body b = new Body(0f, 0f, Shape.createCircle(10f), true);
        world.addBody(a);
        world.addBody(b);
        RevoluteJoint hinge = RevoluteJoint.atWorldPoint(a, b, 0f, 0f);
        hinge.setCollisionLayer(1);
        float torque = 0.5f * b.getInertia();
        hinge.setMotor(1.5f, torque);
        world.addConstraint(hinge);
        // Relative acceleration T·(1/I_A + 1/I_B) until the speed is reached.
        double relative = torque * (1.0 / a.getInertia() + 1.0 / b.getInertia());
        int ticks = (int) Math.round(ticksPerSecond);
        Rigs.run(world, ticks);
        double t = ticks * world.getTimestep();
        System.out.printf("revolute motor %.0f ticks/s: relative ω %.5f vs %.5f; momentum %.3g%n", ticksPerSecond,
            b.getAngularVelocity() - a.getAngularVelocity(), relative * t,
            a.getInertia() * a.getAngularVelocity() + b.getInertia() * b.getAngularVelocity());
        assertEquals(relative * t, b.getAngularVelocity() - a.getAngularVelocity(), 1e-3 * relative * t);
        assertEquals(0.0, a.getInertia() * a.getAngularVelocity() + b.getInertia() * b.getAngularVelocity(),
            1e-4 * b.getInertia() * b.getAngularVelocity());
        assertEquals(torque, hinge.getMotorTorque(), 1e-3 * torque);
        Rigs.run(world, 3 * ticks);
        assertEquals(1.5, b.getAngularVelocity() - a.getAngularVelocity(), 1e-3);
        assertEquals(0.0, hinge.getMotorTorque(), 1e-3 * torque);
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void rotationalSpringOscillatesAtItsFrequency(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        world.setGravity(0f, 0f);
        Body ground = Rigs.anchor(world, 0f, 0f);
        Body disc = new Body(0f, 0f, Shape.createCircle(10f), true);
        world.addBody(disc);
        RevoluteJoint hinge = RevoluteJoint.atWorldPoint(ground, disc, 0f, 0f);
        hinge.setCollisionLayer(1);
        hinge.setSpring(2f, 0f);
        world.addConstraint(hinge);
        disc.setAngularVelocity(3f);
        double period = Oscillation.period(world, hinge::getJointAngle, 0.0, 5);
        System.out.printf("rotational spring %.0f ticks/s: period %.5f s vs 0.5 s%n", ticksPerSecond, period);
        assertEquals(0.5, period, 0.005);
    }
}
