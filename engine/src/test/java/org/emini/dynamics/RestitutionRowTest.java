package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Rows of elastic bodies (Newton's cradle): each collision of equal masses with elasticity 1 swaps
 * the two velocities, so the striker stops, the far body leaves at the striker's speed and kinetic
 * energy is kept, whatever the rate and however many contacts close within one tick.
 */
class RestitutionRowTest {
    private static final float SPEED = 200f;

    /** Velocities of striker then row after one second; the striker starts 20 px short of the row. */
    private static float[] cradle(Shape shape, int count, float gap, float rate) {
        World world = new World();
        world.setTicksPerSecond(rate);
        world.setGravity(0f, 0f);
        Body[] bodies = new Body[count];
        for (int i = 0; i < count; i++) {
            float x = i == 0 ? -40f : (i - 1) * (20f + gap);
            bodies[i] = new Body(x, 0f, shape, true);
            world.addBody(bodies[i]);
        }
        bodies[0].setVelocity(SPEED, 0f);
        for (int t = 0; t < (int) rate; t++) {
            world.tick();
        }
        float[] v = new float[count];
        for (int i = 0; i < count; i++) {
            v[i] = bodies[i].getVelocityX();
            assertEquals(0f, bodies[i].getVelocityY(), 1e-3f, "body " + i + " moves only along the row");
        }
        return v;
    }

    private static Shape elastic(Shape s) {
        s.setElasticity(1f);
        s.setFriction(0f);
        return s;
    }

    @ParameterizedTest(name = "{0} bodies, gap {1} px")
    @CsvSource({"3, 0", "3, 0.1", "5, 0", "5, 0.1", "5, 2", "8, 0.5"})
    void aRowOfBallsPassesTheVelocityDownAtEveryRate(int count, float gap) {
        for (int rate : new int[] {15, 20, 30, 60, 120, 240, 480, 960}) {
            check(cradle(elastic(Shape.createCircle(10f)), count, gap, rate), "balls at " + rate + " ticks/s");
        }
    }

    @Test
    void aRowOfBoxesPassesTheVelocityDownFaceToFace() {
        for (int rate : new int[] {15, 60, 240, 960}) {
            check(cradle(elastic(Shape.createRectangle(20f, 20f)), 4, 0f, rate), "boxes at " + rate + " ticks/s");
        }
    }

    private static void check(float[] v, String what) {
        int last = v.length - 1;
        float energy = 0f;
        for (int i = 0; i < v.length; i++) {
            energy += v[i] * v[i];
            if (i < last) {
                assertEquals(0f, v[i], 0.05f * SPEED, what + ": body " + i + " stops");
            }
        }
        assertTrue(v[last] >= 0.95f * SPEED, what + ": the far body leaves at " + v[last]);
        assertEquals(1f, energy / (SPEED * SPEED), 0.02f, what + ": kinetic energy kept");
    }

    @Test
    void partlyElasticRowsNeverGainEnergy() {
        // Sequential pairwise collisions with e < 1 each lose energy; the row's total may only fall.
        for (float e : new float[] {0.3f, 0.7f, 0.95f}) {
            for (int rate : new int[] {15, 60, 960}) {
                Shape ball = Shape.createCircle(10f);
                ball.setElasticity(e);
                float[] v = cradle(ball, 5, 0.1f, rate);
                float energy = 0f;
                float momentum = 0f;
                for (float vi : v) {
                    energy += vi * vi;
                    momentum += vi;
                }
                assertTrue(energy <= SPEED * SPEED * 1.0001f, "e=" + e + " at " + rate + ": energy " + energy);
                assertEquals(SPEED, momentum, 0.01f * SPEED, "e=" + e + " at " + rate + ": momentum kept");
                // The far ball leaves first and fastest: no ball behind it overtakes it. With e = 0.3 the
                // row ends touching, and a pair may still close a speculative gap of a few thousandths of
                // a pixel at a few thousandths of a px/s (0.003 at 60 ticks/s).
                for (int i = 0; i < v.length - 1; i++) {
                    assertTrue(v[i] <= v[v.length - 1] + 1e-4f * SPEED, "e=" + e + " at " + rate + ": body " + i + " behind the far one");
                }
            }
        }
    }

    @ParameterizedTest(name = "e = {0}, B''s mass {1}, gap {2} px at {3} ticks/s")
    @CsvSource({"1, 1, 40, 20", "1, 1, 37, 20", "0.5, 100, 40, 20", "1, 10, 33.3, 60", "0.8, 3, 5.5, 240"})
    void aHeadOnCollisionEndsWhereTheClosedFormPutsIt(float e, float massB, float gap, int rate) {
        // A bounce is taken at the start of the substep in which the gap closes; the bodies keep their
        // old velocities until it closes (one substep early, the positions were 1 px off at 20 ticks/s).
        World world = new World();
        world.setTicksPerSecond(rate);
        world.setGravity(0f, 0f);
        Shape a = Shape.createRectangle(20f, 20f);
        a.setElasticity(e);
        Shape b = Shape.createRectangle(20f, 20f);
        b.setElasticity(1f);
        b.setMass(massB);
        Body bodyA = new Body(-20f - gap, 0f, a, true);
        Body bodyB = new Body(0f, 0f, b, true);
        bodyA.setVelocity(SPEED, 0f);
        world.addBody(bodyA);
        world.addBody(bodyB);
        for (int t = 0; t < rate; t++) {
            world.tick();
        }
        float impact = gap / SPEED;
        float vA = (1f - e * massB) / (1f + massB) * SPEED;
        float vB = (1f + e) / (1f + massB) * SPEED;
        assertEquals(vA, bodyA.getVelocityX(), 0.01f * SPEED, "A's speed");
        assertEquals(vB, bodyB.getVelocityX(), 0.01f * SPEED, "B's speed");
        assertEquals(-20f + vA * (1f - impact), bodyA.getX(), 0.05f, "A's position");
        assertEquals(vB * (1f - impact), bodyB.getX(), 0.05f, "B's position");
    }
}
