package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A box on a prismatic joint whose axis slopes 30° below the horizontal: without a motor it slides
 * down with a = g·sin θ along the axis and does not turn; with a motor it moves at the motor's
 * speed while the motor holds m·g·sin θ (within its cap), and with a cap below that it slides down
 * with a = g·sin θ − F/m. Distances are those of the engine's integrator (semi-implicit Euler over
 * substeps h): s = ½·a·t·(t + h), which is ½·a·t² to within h/t.
 */
class PrismaticInclineTest {
    private static final double SLOPE = Math.toRadians(30);

    private static World world;
    private static Body box;

    private static PrismaticJoint slide(float ticksPerSecond) {
        world = Rigs.world(ticksPerSecond, 10);
        Body ground = Rigs.anchor(world, 0f, 0f);
        box = new Body(0f, 0f, Shape.createRectangle(30f, 10f), true);
        world.addBody(box);
        PrismaticJoint joint = PrismaticJoint.atWorldPoint(ground, box, 0f, 0f, (float) Math.cos(SLOPE),
            (float) Math.sin(SLOPE));
        joint.setCollisionLayer(1);
        world.addConstraint(joint);
        return joint;
    }

    /** The distance from rest under constant acceleration a after t, integrated over substeps h. */
    private static double distance(double a, double t) {
        double h = world.getTimestep() / world.getConstraintIterations();
        return 0.5 * a * t * (t + h);
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void frictionlessSlideAcceleratesAtGSinTheta(float ticksPerSecond) {
        PrismaticJoint joint = slide(ticksPerSecond);
        int ticks = (int) Math.round(2f * ticksPerSecond);
        Rigs.run(world, ticks);
        double t = ticks * world.getTimestep();
        double a = world.getGravityY() * Math.sin(SLOPE);
        double s = distance(a, t);
        System.out.printf("prismatic %.0f ticks/s: s %.4f px vs ½·g·sin θ·t·(t + h) %.4f px (½·g·sin θ·t² %.4f),"
            + " angle %.2e rad, off axis %.2e px%n", ticksPerSecond, joint.getTranslation(), s, 0.5 * a * t * t,
            box.getAngle(), box.getX() * Math.sin(SLOPE) - box.getY() * Math.cos(SLOPE));
        assertEquals(s, joint.getTranslation(), 1e-4 * s);
        assertEquals(a * t, box.getVelocityX() * Math.cos(SLOPE) + box.getVelocityY() * Math.sin(SLOPE), 0.002 * a * t);
        assertEquals(0.0, box.getAngle(), 1e-4);
        assertEquals(0.0, box.getX() * Math.sin(SLOPE) - box.getY() * Math.cos(SLOPE), 0.01);
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void motorDrivesUphillAtItsSpeedWithinItsCap(float ticksPerSecond) {
        PrismaticJoint joint = slide(ticksPerSecond);
        double weight = box.getMass() * world.getGravityY() * Math.sin(SLOPE);
        float cap = (float) (2.0 * weight);
        joint.setMotor(-25f, cap);
        Rigs.run(world, (int) Math.round(ticksPerSecond));
        double speed = box.getVelocityX() * Math.cos(SLOPE) + box.getVelocityY() * Math.sin(SLOPE);
        System.out.printf("prismatic motor %.0f ticks/s: speed %.4f px/s vs −25, motor force %.3f vs m·g·sin θ %.3f (cap %.3f)%n",
            ticksPerSecond, speed, joint.getMotorForce(), weight, cap);
        assertEquals(-25.0, speed, 1e-3);
        assertEquals(-weight, joint.getMotorForce(), 1e-3 * weight);
        float before = joint.getTranslation();
        Rigs.run(world, (int) Math.round(ticksPerSecond));
        assertEquals(-25.0, joint.getTranslation() - before, 0.01);
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void motorBelowTheLoadSlidesDownWithTheRemainder(float ticksPerSecond) {
        PrismaticJoint joint = slide(ticksPerSecond);
        double g = world.getGravityY() * Math.sin(SLOPE);
        float cap = (float) (0.25 * box.getMass() * g);
        joint.setMotor(-25f, cap);
        int ticks = (int) Math.round(2f * ticksPerSecond);
        Rigs.run(world, ticks);
        double t = ticks * world.getTimestep();
        double a = g - cap / box.getMass();
        System.out.printf("prismatic weak motor %.0f ticks/s: s %.4f px vs %.4f px, force %.3f (cap %.3f)%n",
            ticksPerSecond, joint.getTranslation(), distance(a, t), joint.getMotorForce(), cap);
        assertEquals(distance(a, t), joint.getTranslation(), 1e-4 * distance(a, t));
        assertTrue(Math.abs(joint.getMotorForce()) <= cap * 1.0001, "force " + joint.getMotorForce());
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void limitsStopTheSlide(float ticksPerSecond) {
        PrismaticJoint joint = slide(ticksPerSecond);
        joint.setLimits(-10f, 50f);
        double worst = 0.0;
        for (int i = 0; i < 3 * ticksPerSecond; i++) {
            world.tick();
            worst = Math.max(worst, joint.getTranslation());
        }
        double weight = box.getMass() * world.getGravityY() * Math.sin(SLOPE);
        System.out.printf("prismatic limit %.0f ticks/s: worst %.4f px (limit 50), axial force %.3f vs %.3f%n",
            ticksPerSecond, worst, joint.getAxialForce(), weight);
        assertTrue(worst <= 50.05, "passed the limit: " + worst);
        assertEquals(50.0, joint.getTranslation(), 0.05);
        assertEquals(-weight, joint.getAxialForce(), 0.01 * weight);
    }
}
