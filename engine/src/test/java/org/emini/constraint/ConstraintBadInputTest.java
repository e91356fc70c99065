package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/** Constraints that make no sense are refused when made, with a message naming the call and value. */
class ConstraintBadInputTest {
    private final World world = new World();
    private final Body a = new Body(0f, 0f, Shape.createCircle(5f), true);
    private final Body b = new Body(30f, 0f, Shape.createCircle(5f), true);
    private final Body outside = new Body(60f, 0f, Shape.createCircle(5f), true);

    ConstraintBadInputTest() {
        world.addBody(a);
        world.addBody(b);
    }

    private static void refused(String expectedInMessage, Executable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call);
        assertTrue(e.getMessage().contains(expectedInMessage), e.getMessage());
    }

    @Test
    void jointsRefuseTheSameBodyTwiceBodiesOutsideAWorldAndNaN() {
        refused("Joint: the two bodies must differ", () -> new Joint(a, a, 0f, 0f, 0f, 0f, false));
        refused("Joint: body b", () -> new Joint(a, outside, 0f, 0f, 0f, 0f, false));
        refused("is not in a world", () -> new Joint(outside, a, 0f, 0f, 0f, 0f, true));
        refused("Joint: body a must not be null", () -> new Joint(null, a, 0f, 0f, 0f, 0f, false));
        refused("Joint: anchor a x", () -> new Joint(a, b, Float.NaN, 0f, 0f, 0f, false));
        refused("Joint: anchor b y", () -> new Joint(a, b, 0f, 0f, 0f, Float.POSITIVE_INFINITY, false));
        refused("Joint.atWorldPoint: y", () -> Joint.atWorldPoint(a, b, 0f, Float.NaN, false));
        World other = new World();
        Body elsewhere = new Body(0f, 0f, Shape.createCircle(5f), true);
        other.addBody(elsewhere);
        refused("different worlds", () -> new Joint(a, elsewhere, 0f, 0f, 0f, 0f, false));
        refused("Body.addCollisionLayer", () -> new Joint(a, b, 0f, 0f, 0f, 0f, false).setCollisionLayer(40));
    }

    @Test
    void springsRefuseNegativeSetLengthsCoefficientsAndNaN() {
        refused("Spring: restLength must be a finite number", () -> new Spring(a, b, 0f, 0f, 0f, 0f, Float.NEGATIVE_INFINITY));
        refused("Spring: restLength must be a finite number", () -> new Spring(a, b, 0f, 0f, 0f, 0f, Float.NaN));
        refused("Spring: the two bodies must differ", () -> new Spring(b, b, 0f, 0f, 1f, 0f));
        refused("Spring: body a", () -> new Spring(outside, b, 0f, 0f, 0f, 0f));
        Spring spring = new Spring(a, b, 0f, 0f, 0f, 0f);
        assertEquals(30f, spring.getRestLength(), 1e-5f);
        refused("Spring.setCoefficient: k must be >= 0, was -5.0", () -> spring.setCoefficient(-5f));
        refused("Spring.setCoefficient: k must be a finite number", () -> spring.setCoefficient(Float.POSITIVE_INFINITY));
        refused("Spring.setDamping: c", () -> spring.setDamping(-0.1f));
        refused("Spring.setRestLength: length", () -> spring.setRestLength(-3f));
        refused("Spring.setFrequency: hertz", () -> spring.setFrequency(Float.NaN, 1f));
        refused("Spring.setFrequency: dampingRatio", () -> spring.setFrequency(2f, -1f));
    }

    @Test
    void motorsRefuseNegativeForcesBodiesOutsideAWorldAndNaN() {
        refused("Motor: body", () -> new Motor(outside, 1f, 10f));
        refused("Motor: body must not be null", () -> new Motor(null, 1f, 1f, 10f));
        refused("Motor.setMaxForce: maxForce must be >= 0", () -> new Motor(a, 1f, -10f));
        refused("Motor.setMaxForce: maxForce", () -> new Motor(a, 1f, 1f, Float.NaN));
        refused("Motor.setTargetVelocity: vx", () -> new Motor(a, Float.NaN, 0f, 10f));
        refused("Motor.setTargetAngularVelocity: omega", () -> new Motor(a, Float.POSITIVE_INFINITY, 10f));
        // No limit is a valid limit.
        assertEquals(Float.POSITIVE_INFINITY, new Motor(a, 1f, Float.POSITIVE_INFINITY).getMaxForce(), 0f);
    }

    @Test
    void aConstraintInAnotherWorldThanItsBodiesIsRefusedWhenTicked() {
        World other = new World();
        Joint joint = new Joint(a, b, 0f, 0f, -30f, 0f, false);
        other.addConstraint(joint);
        IllegalStateException e = assertThrows(IllegalStateException.class, other::tick);
        assertTrue(e.getMessage().contains("not in the world being ticked"), e.getMessage());
    }

    @Test
    void removingABodyRemovesItsConstraints() {
        Joint joint = new Joint(a, b, 0f, 0f, -30f, 0f, false);
        Motor motor = new Motor(b, 1f, 10f);
        Spring spring = new Spring(a, b, 0f, 0f, 0f, 0f);
        world.addConstraint(joint);
        world.addConstraint(motor);
        world.addConstraint(spring);
        world.removeBody(b);
        assertEquals(0, world.getConstraintCount());
        world.tick();
    }

    /** Found by the scenario fuzzer: a joint at (0, −1e30) gave NaN forces in its first tick. */
    @org.junit.jupiter.api.Test
    void anchorsFartherThanTheLargestShapeAreRefused() {
        org.emini.world.World world = new org.emini.world.World();
        org.emini.dynamics.Body a = new org.emini.dynamics.Body(0f, 0f, org.emini.shape.Shape.createCircle(2f), false);
        org.emini.dynamics.Body b = new org.emini.dynamics.Body(0f, 20f, org.emini.shape.Shape.createCircle(2f), true);
        world.addBody(a);
        world.addBody(b);
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
            () -> Joint.atWorldPoint(a, b, 0f, -1e30f, false));
        org.junit.jupiter.api.Assertions.assertTrue(e.getMessage().contains("beyond Shape.MAX_EXTENT"), e.getMessage());
    }
}
