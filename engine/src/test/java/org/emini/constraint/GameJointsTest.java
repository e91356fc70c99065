package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.AllocationWindows;
import org.emini.dynamics.Body;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/**
 * The game joints together: a small machine with every one of them allocates nothing per tick,
 * runs the same twice, sleeps and wakes as one island, loses its joints with a removed body, and
 * refuses bad settings naming the call and the value.
 */
class GameJointsTest {
    private static World machine() {
        World world = Rigs.world(60f, 10);
        Body ground = Rigs.anchor(world, 0f, 200f);
        Body arm = new Body(0f, 100f, Shape.createRectangle(60f, 10f), true);
        Body slider = new Body(80f, 100f, Shape.createRectangle(20f, 10f), true);
        Body wheel = new Body(-80f, 140f, Shape.createCircle(10f), true);
        Body bob = new Body(0f, 160f, Shape.createCircle(5f), true);
        Body dragged = new Body(150f, 0f, Shape.createRectangle(10f, 10f), true);
        Body follower = new Body(-150f, 0f, Shape.createRectangle(10f, 10f), true);
        for (Body b : new Body[] {arm, slider, wheel, bob, dragged, follower}) {
            world.addBody(b);
        }
        RevoluteJoint hinge = RevoluteJoint.atWorldPoint(ground, arm, 0f, 100f);
        hinge.setLimits(-0.5f, 0.5f);
        hinge.setMotor(1f, 1e6f);
        hinge.setSpring(1f, 0.2f);
        hinge.setCollisionLayer(1);
        world.addConstraint(hinge);
        PrismaticJoint slide = PrismaticJoint.atWorldPoint(arm, slider, 80f, 100f, 1f, 0f);
        slide.setLimits(-20f, 20f);
        slide.setMotor(10f, 1e5f);
        slide.setCollisionLayer(2);
        world.addConstraint(slide);
        WheelJoint axle = WheelJoint.atWorldPoint(arm, wheel, -80f, 140f, 0f, 1f);
        axle.setSpring(4f, 0.7f);
        axle.setMotor(5f, 1e6f);
        axle.setCollisionLayer(3);
        world.addConstraint(axle);
        world.addConstraint(DistanceJoint.rope(arm, bob, 0f, 0f, 0f, 0f, 70f));
        MouseJoint drag = new MouseJoint(dragged, 150f, 0f, 1e5f);
        drag.setTarget(180f, 20f);
        world.addConstraint(drag);
        MotorJoint motor = new MotorJoint(ground, follower, 1e5f, 1e6f);
        motor.setLinearOffset(-120f, -230f);
        world.addConstraint(motor);
        Joint weld = Joint.atWorldPoint(arm, ground, 0f, 150f, true);
        weld.setStiffness(2f, 2f, 0.5f);
        weld.setBreakForce(1e9f);
        world.addConstraint(weld);
        return world;
    }

    @Test
    void ticksAllocateNothingAndRepeatBitForBit() {
        World world = machine();
        Rigs.run(world, 200);
        int[] windows = {0};
        AllocationWindows allocated = AllocationWindows.measure(5, () -> {
            Rigs.run(world, 50);
            windows[0]++;
        });
        assertEquals(0L, allocated.least(), "50 ticks, " + allocated);
        World again = machine();
        Rigs.run(again, 200 + windows[0] * 50);
        for (int i = 0; i < world.getBodyCount(); i++) {
            assertEquals(Float.floatToIntBits(world.getBody(i).getX()), Float.floatToIntBits(again.getBody(i).getX()));
            assertEquals(Float.floatToIntBits(world.getBody(i).getAngle()),
                Float.floatToIntBits(again.getBody(i).getAngle()));
        }
    }

    @Test
    void jointsJoinIslandsAndGoWithTheirBodies() {
        World world = Rigs.world(60f, 10);
        world.setSleepingEnabled(true);
        Body ground = Rigs.anchor(world, 0f, 0f);
        Body a = new Body(0f, 20f, Shape.createCircle(5f), true);
        Body b = new Body(0f, 40f, Shape.createCircle(5f), true);
        world.addBody(a);
        world.addBody(b);
        world.addConstraint(RevoluteJoint.atWorldPoint(ground, a, 0f, 0f));
        world.addConstraint(DistanceJoint.rope(a, b, 0f, 0f, 0f, 0f, 20f));
        Rigs.run(world, 600);
        assertTrue(a.isSleeping() && b.isSleeping(), "asleep: " + a.isSleeping() + ", " + b.isSleeping());
        MouseJoint drag = new MouseJoint(b, 0f, 40f, 1e5f);
        world.addConstraint(drag);
        drag.setTarget(30f, 40f);
        world.tick();
        assertTrue(!a.isSleeping() && !b.isSleeping(), "the drag woke the island");
        world.removeBody(a);
        assertEquals(1, world.getConstraintCount());
        assertTrue(world.getConstraint(0) == drag);
    }

    private static void refused(String expectedInMessage, Executable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call);
        assertTrue(e.getMessage().contains(expectedInMessage), e.getMessage());
    }

    @Test
    void settingsReadBack() {
        World world = new World();
        Body a = new Body(0f, 0f, Shape.createCircle(5f), true);
        Body b = new Body(30f, 0f, Shape.createCircle(5f), true);
        world.addBody(a);
        world.addBody(b);
        WheelJoint wheel = WheelJoint.atWorldPoint(a, b, 30f, 0f, 0f, 1f);
        wheel.setLimits(-5f, 8f);
        wheel.setMotor(3f, 40f);
        assertTrue(wheel.isLimitEnabled() && wheel.isMotorEnabled());
        assertEquals(-5f, wheel.getLowerLimit());
        assertEquals(8f, wheel.getUpperLimit());
        assertEquals(3f, wheel.getMotorSpeed());
        assertEquals(40f, wheel.getMaxMotorTorque());
        PrismaticJoint slide = PrismaticJoint.atWorldPoint(a, b, 30f, 0f, 1f, 0f);
        assertEquals(0f, slide.getSpringHertz());
        slide.setMotor(-25f, 100f);
        slide.setSpring(2f, 0.5f);
        assertEquals(-25f, slide.getMotorSpeed());
        assertEquals(100f, slide.getMaxMotorForce());
        assertEquals(2f, slide.getSpringHertz());
        assertEquals(0.5f, slide.getSpringDampingRatio());
    }

    @Test
    void badSettingsAreRefusedNamingTheCallAndTheValue() {
        World world = new World();
        Body a = new Body(0f, 0f, Shape.createCircle(5f), true);
        Body b = new Body(30f, 0f, Shape.createCircle(5f), true);
        world.addBody(a);
        world.addBody(b);
        RevoluteJoint hinge = RevoluteJoint.atWorldPoint(a, b, 15f, 0f);
        refused("RevoluteJoint.setLimits: lower (1.0) must not exceed upper (-1.0)", () -> hinge.setLimits(1f, -1f));
        refused("RevoluteJoint.setMotor: max must be >= 0", () -> hinge.setMotor(1f, -2f));
        refused("RevoluteJoint.setSpring: hertz", () -> hinge.setSpring(Float.NaN, 1f));
        refused("RevoluteJoint: the two bodies must differ", () -> new RevoluteJoint(a, a, 0f, 0f, 0f, 0f));
        refused("PrismaticJoint: the axis (0.0, 0.0) has no direction", () -> new PrismaticJoint(a, b, 0f, 0f, 0f, 0f, 0f, 0f));
        refused("WheelJoint.atWorldPoint: axis y", () -> WheelJoint.atWorldPoint(a, b, 0f, 0f, 0f, Float.NaN));
        refused("DistanceJoint.rope: maxLength must be > 0, was -3.0",
            () -> DistanceJoint.rope(a, b, 0f, 0f, 0f, 0f, -3f));
        refused("DistanceJoint.setLengthRange: min must be >= 0", () -> new DistanceJoint(a, b, 0f, 0f, 0f, 0f)
            .setLengthRange(-1f, 3f));
        refused("MouseJoint: maxForce", () -> new MouseJoint(a, 0f, 0f, -1f));
        refused("MouseJoint.setSpring: hertz must be > 0, was 0.0", () -> new MouseJoint(a, 0f, 0f, 1f).setSpring(0f, 1f));
        refused("MotorJoint.setLinearOffset: x", () -> new MotorJoint(a, b, 1f, 1f).setLinearOffset(Float.NaN, 0f));
        refused("Joint.setBreakForce: maxForce", () -> Joint.atWorldPoint(a, b, 0f, 0f, false).setBreakForce(-1f));
        refused("Motor.setBreakForce: maxForce", () -> new Motor(a, 1f, 1f).setBreakForce(Float.NaN));
        refused("Joint.setStiffness: dampingRatio", () -> Joint.atWorldPoint(a, b, 0f, 0f, true).setStiffness(1f, 1f, -1f));
    }
}
