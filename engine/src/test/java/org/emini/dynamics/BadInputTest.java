package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/** NaN and infinite input is refused at the call that introduces it, with a message naming it. */
class BadInputTest {
    private static void refused(String expectedInMessage, Executable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call);
        assertTrue(e.getMessage().contains(expectedInMessage), e.getMessage());
    }

    @Test
    void bodyStateRefusesNonFiniteValues() {
        Shape shape = Shape.createCircle(5f);
        Body b = new Body(0f, 0f, shape, true);
        refused("Body(x, y, shape, dynamic): x", () -> new Body(Float.NaN, 0f, shape, true));
        refused("Body.setPosition: y", () -> b.setPosition(0f, Float.POSITIVE_INFINITY));
        refused("Body.setVelocity: vx", () -> b.setVelocity(Float.NaN, 0f));
        refused("Body.setAngularVelocity", () -> b.setAngularVelocity(Float.NEGATIVE_INFINITY));
        refused("Body.setAngle", () -> b.setAngle(Float.NaN));
        refused("Body.applyForce: fy", () -> b.applyForce(0f, Float.NaN));
        refused("Body.applyImpulse: jx", () -> b.applyImpulse(Float.NaN, 0f));
        refused("Body.applyTorque", () -> b.applyTorque(Float.NaN));
        refused("Body.addCollisionLayer", () -> b.addCollisionLayer(32));
        refused("shape", () -> new Body(0f, 0f, null, true));
        // Finite inputs whose results overflow a float (found by the setter fuzzer): refused, nothing applied.
        // Written against Float.MAX_VALUE so the double flavour's run overflows its own range.
        float big = 0.9f * Float.MAX_VALUE;
        refused("Body.applyImpulseAt: the moment", () -> b.applyImpulseAt(-Float.MAX_VALUE, -1e30f, -1e30f, -1e30f));
        refused("Body.applyForceAt: the moment", () -> b.applyForceAt(big, big, -big, big));
        assertTrue(b.getAngularVelocity() == 0f && b.getVelocityX() == 0f, "nothing was applied");
        b.setVelocity(big, 0f);
        refused("Body.applyImpulse: the velocity", () -> b.applyImpulse(big, 0f));
        refused("rule TOO_LARGE", () -> Shape.createCircle(Float.MAX_VALUE));
        refused("rule TOO_LARGE", () -> Shape.createRectangle(3e7f, 3e7f));
    }

    @Test
    void massAndMaterialRefuseBadValues() {
        Shape shape = Shape.createRectangle(10f, 10f);
        assertThrows(IllegalArgumentException.class, () -> shape.setMass(Float.NaN));
        assertThrows(IllegalArgumentException.class, () -> shape.setMass(0f));
        assertThrows(IllegalArgumentException.class, () -> shape.setMass(Float.POSITIVE_INFINITY));
        refused("Shape.setMass: mass " + Float.MIN_VALUE, () -> shape.setMass(Float.MIN_VALUE));
        float big = 0.9f * Float.MAX_VALUE;
        refused("Shape.setMass: mass " + big, () -> shape.setMass(big));
        assertThrows(IllegalArgumentException.class, () -> shape.setFriction(1.5f));
        assertThrows(IllegalArgumentException.class, () -> shape.setElasticity(Float.NaN));
    }

    @Test
    void worldSettingsRefuseBadValues() {
        World world = new World();
        refused("World.setGravity: gx", () -> world.setGravity(Float.NaN, 0f));
        refused("World.setTimestep", () -> world.setTimestep(0f));
        refused("World.setTimestep", () -> world.setTimestep(Float.NaN));
        refused("World.setTimestep: seconds must be >= 1.0E-6", () -> world.setTimestep(Float.MIN_VALUE));
        refused("World.setConstraintIterations", () -> world.setConstraintIterations(0));
        refused("World.setDampingLateral", () -> world.setDampingLateral(2f));
        refused("SolverSettings.setContactHertz", () -> world.getSolverSettings().setContactHertz(Float.NaN));
        refused("SolverSettings.setSpeculativeSweep: factor must be >= 0", () -> world.getSolverSettings().setSpeculativeSweep(-0.5f));
        refused("SolverSettings.setSpeculativeSweep", () -> world.getSolverSettings().setSpeculativeSweep(Float.POSITIVE_INFINITY));
        Body b = new Body(0f, 0f, Shape.createCircle(1f), true);
        world.addBody(b);
        refused("already belongs", () -> world.addBody(b));
    }
}
