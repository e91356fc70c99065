package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A box hangs at rest from a pin (load m·g), a rope, a hinge, and a motor holds another still:
 * each holds for good with a break force 1% above its load, and breaks in its first tick under
 * load with a break force 1% below it: the tick's step data lists it, the world no longer has it,
 * and the body falls freely from then on.
 */
class BreakableJointTest {
    /** A box hanging at rest 40 px below a static anchor, held by the given constraint. */
    private interface Holder {
        Constraint hold(Body anchor, Body box);
    }

    private static final Holder[] HOLDERS = {
        (a, b) -> Joint.atWorldPoint(a, b, 0f, 0f, false),
        (a, b) -> DistanceJoint.rope(a, b, 0f, 0f, 0f, 0f, 40f),
        (a, b) -> RevoluteJoint.atWorldPoint(a, b, 0f, 0f),
        (a, b) -> new Spring(a, b, 0f, 0f, 0f, 0f),
    };

    private static Constraint breakable(Constraint c, float force) {
        if (c instanceof TwoBodyConstraint) {
            ((TwoBodyConstraint) c).setBreakForce(force);
        } else {
            ((Motor) c).setBreakForce(force);
        }
        return c;
    }

    private static int ticksHeld(float ticksPerSecond, Holder holder, float loadShare) {
        World world = Rigs.world(ticksPerSecond, 10);
        Body anchor = Rigs.anchor(world, 0f, 0f);
        Body box = new Body(0f, 40f, Shape.createRectangle(10f, 10f), true);
        world.addBody(box);
        box.setRotatable(false);
        Constraint c = breakable(holder.hold(anchor, box), loadShare * box.getMass() * world.getGravityY());
        world.addConstraint(c);
        for (int i = 0; i < 3 * ticksPerSecond; i++) {
            world.tick();
            if (world.getConstraintCount() == 0) {
                assertEquals(1, world.getStepData().getBrokenCount());
                assertSame(c, world.getStepData().getBrokenConstraint(0));
                float y = box.getY();
                float vy = box.getVelocityY();
                world.tick();
                assertEquals(0, world.getStepData().getBrokenCount());
                assertEquals(vy + world.getGravityY() * world.getTimestep(), box.getVelocityY(), 1e-3);
                assertEquals(true, box.getY() > y);
                return i + 1;
            }
        }
        return -1;
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void breaksAboveItsLoadAndNotBelow(float ticksPerSecond) {
        for (Holder holder : HOLDERS) {
            assertEquals(-1, ticksHeld(ticksPerSecond, holder, 1.01f), "held at 1.01 × the load");
            assertEquals(1, ticksHeld(ticksPerSecond, holder, 0.99f), "broke at 0.99 × the load");
        }
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void motorBreaksWhenItsForceExceedsTheBreakForce(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        Body box = new Body(0f, 0f, Shape.createRectangle(10f, 10f), true);
        world.addBody(box);
        float weight = box.getMass() * world.getGravityY();
        // A motor that holds the box still against gravity needs m·g.
        Motor hold = new Motor(box, 0f, 0f, 2f * weight);
        hold.setOrthogonal(true);
        hold.setBreakForce(1.01f * weight);
        world.addConstraint(hold);
        Rigs.run(world, (int) Math.round(ticksPerSecond));
        assertEquals(1, world.getConstraintCount());
        assertEquals(weight, hold.getForce(), 1e-3 * weight);
        hold.setBreakForce(0.99f * weight);
        world.tick();
        assertEquals(0, world.getConstraintCount());
        assertSame(hold, world.getStepData().getBrokenConstraint(0));
    }
}
