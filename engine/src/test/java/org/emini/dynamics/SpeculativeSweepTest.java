package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * The speculative sweep ({@link SolverSettings#setSpeculativeSweep}): two small boxes fly at each other
 * faster than their size a tick. The fast-body pass sweeps fast bodies against static and moving
 * kinematic ones (and bullets against everything), so between two ordinary dynamic bodies only the
 * sweep catches the pair before it has passed through.
 */
class SpeculativeSweepTest {
    /** The left box's final x minus the right one's: negative while they are still in order. */
    private static float order(float sweep) {
        World world = new World();
        world.setTicksPerSecond(60f);
        world.setGravity(0f, 0f);
        world.getSolverSettings().setSpeculativeSweep(sweep);
        Shape box = Shape.createRectangle(10f, 10f);
        Body left = new Body(-40f, 0f, box, true);
        Body right = new Body(40f, 0f, box, true);
        world.addBody(left);
        world.addBody(right);
        // 1,200 px/s apart: 20 px a tick, twice a box's size.
        left.setVelocity(600f, 0f);
        right.setVelocity(-600f, 0f);
        for (int tick = 0; tick < 30; tick++) {
            world.tick();
        }
        return left.getX() - right.getX();
    }

    @Test
    void withTheSweepTwoFastBoxesMeet() {
        assertEquals(1f, new SolverSettings().getSpeculativeSweep());
        float order = order(1f);
        assertTrue(order < -9f, "the boxes passed through each other: left - right = " + order);
    }

    @Test
    void withoutItTheyPassThroughEachOther() {
        float order = order(0f);
        assertTrue(order > 0f, "without the sweep the boxes still met: left - right = " + order);
    }

    /** A kinematic paddle at 1,200 px/s towards a box at rest: the box's x minus the paddle's at the end. */
    private static float paddleLead(float sweep) {
        World world = new World();
        world.setTicksPerSecond(60f);
        world.setGravity(0f, 0f);
        world.getSolverSettings().setSpeculativeSweep(sweep);
        Body paddle = new Body(-60f, 0f, Shape.createRectangle(10f, 40f), false);
        paddle.setKinematic(true);
        paddle.setVelocity(1200f, 0f);
        Body box = new Body(0f, 0f, Shape.createRectangle(10f, 10f), true);
        world.addBody(paddle);
        world.addBody(box);
        for (int tick = 0; tick < 20; tick++) {
            world.tick();
        }
        return box.getX() - paddle.getX();
    }

    @Test
    void aFastKinematicBodyPushesABodyWithOrWithoutTheSweep() {
        // The fast-body pass sweeps the box in the moving kinematic body's frame, so it catches the hit
        // when the pair's speculative contact, without the sweep, does not.
        float with = paddleLead(1f);
        assertTrue(with > 9f, "with the sweep the paddle passed the box: box - paddle = " + with);
        float without = paddleLead(0f);
        assertTrue(without > 9f, "without the sweep the paddle passed the box: box - paddle = " + without);
    }
}
