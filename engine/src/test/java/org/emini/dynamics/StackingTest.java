package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.emini.collision.Collider;
import org.emini.collision.Manifold;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * Stacks hold at the original engine's defaults (20 ticks per second, 10 iterations, 20 px boxes):
 * the original holds a tower of 10 and loses one of 15; pymunk loses 10. Ours must hold 40 boxes
 * and a 20-row pyramid for 60 s: every box drifts less than 1 px sideways and turns less than
 * 0.05 rad, and neighbours overlap by less than 0.5 px.
 */
class StackingTest {
    static final float SIZE = 20f;

    /** Largest overlap between two bodies in contact (px), measured at the current poses. */
    static float maxOverlap(World world) {
        Collider collider = new Collider();
        Manifold m = new Manifold();
        float worst = 0f;
        for (int k = 0; k < world.getContactCount(); k++) {
            Contact c = world.getContact(k);
            Body a = c.getBodyA();
            Body b = c.getBodyB();
            collider.collide(a.getShape(), a.getX(), a.getY(), a.getCos(), a.getSin(),
                b.getShape(), b.getX(), b.getY(), b.getCos(), b.getSin(), 0f, m);
            for (int p = 0; p < m.pointCount; p++) {
                worst = Math.max(worst, -m.separation[p]);
            }
        }
        return worst;
    }

    /** Runs the stack and checks drift, turn and overlap against the criteria. */
    static void holds(World world, Body[] boxes, float seconds) {
        float[] x0 = new float[boxes.length];
        for (int i = 0; i < boxes.length; i++) {
            x0[i] = boxes[i].getX();
        }
        float worstOverlap = 0f;
        float worstDrift = 0f;
        float worstTurn = 0f;
        int ticks = (int) Math.round(seconds / world.getTimestep());
        for (int t = 0; t < ticks; t++) {
            world.tick();
            if (t % 10 == 9) {
                worstOverlap = Math.max(worstOverlap, maxOverlap(world));
            }
            for (int i = 0; i < boxes.length; i++) {
                worstDrift = Math.max(worstDrift, Math.abs(boxes[i].getX() - x0[i]));
                worstTurn = Math.max(worstTurn, Math.abs(boxes[i].getAngle()));
            }
        }
        String summary = "drift " + worstDrift + " px, turn " + worstTurn + " rad, overlap " + worstOverlap + " px";
        assertTrue(worstDrift < 1f, summary);
        assertTrue(worstTurn < 0.05f, summary);
        assertTrue(worstOverlap < 0.5f, summary);
    }

    /** Shifts every box sideways by up to ±amount px: real stacks are never perfectly aligned. */
    static void jitter(Body[] boxes, float amount, long seed) {
        Random random = new Random(seed);
        for (Body b : boxes) {
            b.setPosition(b.getX() + (random.nextFloat() * 2f - 1f) * amount, b.getY());
        }
    }

    @Test
    void towerOf40BoxesStandsForAMinuteAtTheDefaults() {
        World world = new World();
        holds(world, Scenes.tower(world, 40, SIZE), 60f);
    }

    @Test
    void pyramidOf20RowsStandsForAMinuteAtTheDefaults() {
        World world = new World();
        holds(world, Scenes.pyramid(world, 20, SIZE), 60f);
    }

    @Test
    void misalignedTowerOf20StandsAtTheDefaults() {
        World world = new World();
        Body[] boxes = Scenes.tower(world, 20, SIZE);
        jitter(boxes, 0.1f, 1);
        holds(world, boxes, 60f);
    }

    @Test
    void misalignedTowerOf40StandsAt60TicksPerSecond() {
        World world = new World();
        world.setTicksPerSecond(60f);
        Body[] boxes = Scenes.tower(world, 40, SIZE);
        jitter(boxes, 0.1f, 2);
        holds(world, boxes, 60f);
    }

    @Test
    void dynamicIterationsStopEarlyOnARestingStackAndKeepItStanding() {
        World world = new World();
        world.setConstraintIterationDynamic(true);
        Body[] boxes = Scenes.tower(world, 10, SIZE);
        Scenes.run(world, 2f);
        int used = 0;
        for (int t = 0; t < 100; t++) {
            world.tick();
            used += world.getLastIterationCount();
        }
        assertTrue(used < 100 * world.getConstraintIterations(), "iterations used " + used);
        holds(world, boxes, 20f);
    }
}
