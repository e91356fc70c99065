package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.Consumer;
import org.emini.event.Event;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * The one rule for changing a world while it ticks: structural changes (bodies, constraints,
 * forces, events, emitters, the landscape) made from an external force, a constraint or an event
 * listener are applied in order when the tick ends; tick() is not re-entrant; while the solver holds
 * its copies of the bodies (a constraint's callbacks) velocity and force changes reach the copies and
 * pose or shape changes are refused.
 */
class ChangesDuringTickTest {
    /** A constraint that runs an action in its prepare and does nothing else. */
    static final class OnPrepare implements Constraint {
        private final Consumer<SolverStep> action;

        OnPrepare(Consumer<SolverStep> action) {
            this.action = action;
        }

        @Override
        public boolean concernsBody(Body body) {
            return false;
        }

        @Override
        public void prepare(SolverStep step) {
            action.accept(step);
        }

        @Override
        public void warmStart(SolverStep step) {
        }

        @Override
        public float solve(SolverStep step, boolean useBias) {
            return 0f;
        }

        @Override
        public void finish(SolverStep step) {
        }

        @Override
        public float getForce() {
            return 0f;
        }
    }

    private static World pile(Body[] out) {
        World world = new World();
        Scenes.ground(world, 0f, 400f);
        for (int i = 0; i < out.length; i++) {
            out[i] = new Body(-50f + 25f * i, -10f, Shape.createRectangle(20f, 20f), true);
            world.addBody(out[i]);
        }
        return world;
    }

    @Test
    void removingABodyFromAConstraintsPrepareTakesEffectWhenTheTickEnds() {
        Body[] boxes = new Body[4];
        World world = pile(boxes);
        int[] calls = new int[1];
        world.addConstraint(new OnPrepare(step -> {
            if (calls[0]++ == 2) {
                assertTrue(world.removeBody(boxes[1]));
                assertFalse(world.removeBody(boxes[1]), "a second removal of the same body");
                assertSame(world, boxes[1].getWorld(), "still there until the tick ends");
            }
        }));
        for (int t = 0; t < 10; t++) {
            world.tick();
        }
        assertNull(boxes[1].getWorld());
        assertEquals(4, world.getBodyCount());
    }

    @Test
    void removingBodiesFromACollisionListenerTakesEffectWhenTheTickEnds() {
        Body[] boxes = new Body[6];
        World world = pile(boxes);
        world.addEvent(Event.createCollisionEvent(null, null, true, true, true, true));
        int[] seenCounts = new int[1];
        world.setPhysicsEventListener((event, parameter) -> {
            Body b = ((Contact) parameter).getBodyA().isDynamic() ? ((Contact) parameter).getBodyA() : ((Contact) parameter).getBodyB();
            seenCounts[0] = Math.max(seenCounts[0], world.getBodyCount());
            world.removeBody(b);
        });
        for (int t = 0; t < 10; t++) {
            world.tick();
        }
        assertEquals(7, seenCounts[0], "the lists did not change while the listener ran");
        assertEquals(1, world.getBodyCount(), "every box touching the ground was removed");
    }

    @Test
    void addingFromAListenerAndAForceAppearsAfterTheTick() {
        Body[] boxes = new Body[1];
        World world = pile(boxes);
        Body extra = new Body(100f, -100f, Shape.createCircle(5f), true);
        Body extra2 = new Body(150f, -100f, Shape.createCircle(5f), true);
        world.addExternalForce((w, dt) -> {
            if (w.getTickCount() == 1) {
                w.addBody(extra2);
                assertThrows(IllegalArgumentException.class, () -> w.addBody(extra2), "added twice");
            }
        });
        world.addEvent(Event.createPositionEvent(boxes[0], null, -1e6f, -1e6f, 1e6f, 1e6f));
        world.setPhysicsEventListener((event, parameter) -> {
            if (extra.getWorld() == null && world.getBodyCount() == 2) {
                world.addBody(extra);
                assertEquals(2, world.getBodyCount());
            }
        });
        world.tick();
        assertEquals(3, world.getBodyCount());
        world.tick();
        assertEquals(4, world.getBodyCount());
        assertSame(world, extra2.getWorld());
    }

    @Test
    void tickIsNotReentrant() {
        Body[] boxes = new Body[1];
        World world = pile(boxes);
        world.addEvent(Event.createPositionEvent(null, null, -1e6f, -1e6f, 1e6f, 1e6f));
        world.setPhysicsEventListener((event, parameter) -> world.tick());
        IllegalStateException e = assertThrows(IllegalStateException.class, world::tick);
        assertTrue(e.getMessage().startsWith("World.tick: called during a tick"), e.getMessage());
        world.setPhysicsEventListener(null);
        world.tick();
        assertEquals(2, world.getTickCount());
    }

    /** The manual's jump: a constraint's prepare sets a velocity or applies an acceleration, and the body moves by it this tick. */
    @Test
    void aVelocitySetInAConstraintsPrepareIsKept() {
        Body[] boxes = new Body[1];
        World world = pile(boxes);
        for (int t = 0; t < 20; t++) {
            world.tick();
        }
        boolean[] jump = {true};
        world.addConstraint(new OnPrepare(step -> {
            if (jump[0]) {
                boxes[0].setVelocity(0f, -200f);
                jump[0] = false;
            }
        }));
        world.tick();
        float g = world.getGravityY() * world.getTimestep();
        assertEquals(-200f + g, boxes[0].getVelocityY(), 1f);
        assertTrue(boxes[0].getY() < -10f - 5f, "the box left the ground: y " + boxes[0].getY());
    }

    @Test
    void anAccelerationAppliedInAConstraintsPrepareActsThisTick() {
        Body[] boxes = new Body[1];
        World world = pile(boxes);
        for (int t = 0; t < 20; t++) {
            world.tick();
        }
        boolean[] jump = {true};
        world.addConstraint(new OnPrepare(step -> {
            if (jump[0]) {
                boxes[0].applyAcceleration(0f, -5000f);
                jump[0] = false;
            }
        }));
        world.tick();
        float expected = (world.getGravityY() - 5000f) * world.getTimestep();
        assertEquals(expected, boxes[0].getVelocityY(), 0.05f * Math.abs(expected));
    }

    @Test
    void movingABodyFromAConstraintIsRefusedWithAClearError() {
        Body[] boxes = new Body[1];
        World world = pile(boxes);
        world.addConstraint(new OnPrepare(step -> boxes[0].setPosition(0f, -100f)));
        IllegalStateException e = assertThrows(IllegalStateException.class, world::tick);
        assertTrue(e.getMessage().startsWith("Body.setPosition: cannot change a body's pose"), e.getMessage());
    }
}
