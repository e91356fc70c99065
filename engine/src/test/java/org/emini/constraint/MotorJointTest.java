package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A motor joint drives a box to 150 px right of and 1 rad turned from a static base, against
 * gravity: it gets there and stays, holding the box's weight, its force and torque within the caps;
 * with the base turned, the target turns with it.
 */
class MotorJointTest {
    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void drivesTheBodyToItsTargetOffset(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        Body base = Rigs.anchor(world, 0f, 0f);
        Body box = new Body(0f, 50f, Shape.createRectangle(20f, 20f), true);
        world.addBody(box);
        float weight = box.getMass() * world.getGravityY();
        float maxForce = 5f * weight;
        float maxTorque = 50f * box.getInertia();
        MotorJoint motor = new MotorJoint(base, box, maxForce, maxTorque);
        assertEquals(50f, motor.getLinearOffsetY(), 1e-4);
        motor.setLinearOffset(150f, 50f);
        motor.setAngularOffset(1f);
        world.addConstraint(motor);
        double peakForce = 0.0;
        double peakTorque = 0.0;
        for (int i = 0; i < 4 * ticksPerSecond; i++) {
            world.tick();
            peakForce = Math.max(peakForce, motor.getForce());
            peakTorque = Math.max(peakTorque, motor.getTorque());
        }
        System.out.printf("motor joint %.0f ticks/s: at (%.4f, %.4f) angle %.5f; force %.4f weights (peak %.3f, cap 5),"
            + " peak torque %.3f of the cap%n", ticksPerSecond, box.getX(), box.getY(), box.getAngle(),
            motor.getForce() / weight, peakForce / weight, peakTorque / maxTorque);
        // The spring holds the weight with a sag of g/ω² (1 px at 5 Hz): the target is reached to within it.
        double sag = world.getGravityY() / Math.pow(2 * Math.PI * 5, 2);
        assertEquals(150.0, box.getX(), 0.01);
        assertEquals(50.0 + sag, box.getY(), 0.01);
        assertEquals(1.0, box.getAngle(), 1e-3);
        assertEquals(weight, motor.getForce(), 1e-3 * weight);
        assertTrue(peakForce <= maxForce * 1.0001, "force over the cap " + peakForce);
        assertTrue(peakTorque <= maxTorque * 1.0001, "torque over the cap " + peakTorque);
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void theTargetTurnsWithTheReferenceBody(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        world.setGravity(0f, 0f);
        Body base = new Body(0f, 0f, Shape.createRectangle(10f, 10f), false);
        base.setAngle((float) (Math.PI / 2));
        world.addBody(base);
        Body box = new Body(0f, 0f, Shape.createRectangle(20f, 20f), true);
        world.addBody(box);
        MotorJoint motor = new MotorJoint(base, box, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY);
        motor.setCollisionLayer(2);
        motor.setLinearOffset(100f, 0f);
        world.addConstraint(motor);
        Rigs.run(world, (int) Math.round(4 * ticksPerSecond));
        // A's x axis points down the screen at 90°: the target is (0, 100).
        assertEquals(0.0, box.getX(), 0.01);
        assertEquals(100.0, box.getY(), 0.01);
        assertEquals(0.0, box.getAngle(), 1e-3);
    }
}
