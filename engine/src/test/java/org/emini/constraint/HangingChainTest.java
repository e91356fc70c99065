package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/** A chain of 30 links on loose pins keeps every joint closed, hanging still or swinging down. */
class HangingChainTest {
    private static final int LINKS = 30;
    private static final float LENGTH = 20f;

    private static final class Chain {
        final World world;
        final Joint[] joints = new Joint[LINKS];
        Body last;

        Chain(World world, boolean horizontal) {
            this.world = world;
            Body previous = Rigs.anchor(world, 0f, 0f);
            Shape link = Shape.createRectangle(LENGTH, 4f);
            for (int i = 0; i < LINKS; i++) {
                float along = LENGTH * (i + 0.5f);
                Body b = horizontal ? new Body(along, 0f, link, true) : new Body(0f, along, link, true);
                if (!horizontal) {
                    b.setAngle((float) (Math.PI / 2));
                }
                world.addBody(b);
                float pin = LENGTH * i;
                joints[i] = horizontal ? Joint.atWorldPoint(previous, b, pin, 0f, false)
                    : Joint.atWorldPoint(previous, b, 0f, pin, false);
                // Neighbours overlap at the pins: alternate layers keep them from colliding.
                joints[i].setCollisionLayer(i % 2);
                world.addConstraint(joints[i]);
                previous = b;
            }
            last = previous;
        }

        /** Runs and returns the widest joint gap seen after any tick. */
        double run(float seconds) {
            double worst = 0.0;
            int ticks = (int) Math.round(seconds / world.getTimestep());
            for (int t = 0; t < ticks; t++) {
                world.tick();
                for (Joint j : joints) {
                    worst = Math.max(worst, Rigs.gap(j));
                }
            }
            return worst;
        }
    }

    @Test
    void chainHangingUnderGravityKeepsEveryGapBelowHalfAPixel() {
        // The original's defaults: 20 ticks per second, 10 iterations.
        Chain chain = new Chain(Rigs.world(20f, 10), false);
        double worst = chain.run(10f);
        System.out.printf("30-link chain hanging, 20 Hz: widest gap %.4f px, end at y %.3f (straight: %.1f)%n",
            worst, chain.last.getY(), LENGTH * (LINKS - 0.5f));
        assertTrue(worst < 0.5, "widest gap " + worst);
        // Hanging straight: the joints' softness stretches it by well under a pixel in all.
        assertEquals(LENGTH * (LINKS - 0.5f), chain.last.getY(), 1.0);
        assertEquals(0.0, chain.last.getX(), 1e-3);
    }

    @Test
    void changingTheTimestepAndIterationsDoesNotJoltAHangingChain() {
        // Impulses are per substep and are rescaled when it changes. The chain only settles to the
        // joints' new stiffness (the cap is higher at the shorter substep): its soft sag of 0.9 px
        // shrinks by about 0.3 px, with some overshoot.
        Chain chain = new Chain(Rigs.world(20f, 10), false);
        chain.run(5f);
        float y = chain.last.getY();
        chain.world.setTicksPerSecond(60f);
        chain.world.setConstraintIterations(4);
        double worstGap = 0.0;
        double worstMove = 0.0;
        for (int t = 0; t < 120; t++) {
            worstGap = Math.max(worstGap, chain.run(1f / 60f));
            worstMove = Math.max(worstMove, Math.abs(chain.last.getY() - y));
            if (t == 60) {
                chain.world.setConstraintIterationDynamic(true);
            }
        }
        System.out.printf("hanging chain switched from 20 Hz x 10 to 60 Hz x 4, then dynamic: end moved ≤ %.4f px, gap ≤ %.4f px%n",
            worstMove, worstGap);
        assertTrue(worstGap < 0.5, "widest gap " + worstGap);
        assertTrue(worstMove < 1.0, "the end moved " + worstMove);
    }

    @Test
    void chainReleasedHorizontallyKeepsEveryGapBelowHalfAPixelWhileItSwings() {
        Chain chain = new Chain(Rigs.world(60f, 10), true);
        double worst = chain.run(10f);
        System.out.printf("30-link chain released horizontally, 60 Hz: widest gap %.4f px%n", worst);
        assertTrue(worst < 0.5, "widest gap " + worst);
    }

    @Test
    void chainReleasedHorizontallyAtTheOriginalDefaultsStaysBelowHalfAPixel() {
        Chain chain = new Chain(Rigs.world(20f, 10), true);
        double worst = chain.run(10f);
        System.out.printf("30-link chain released horizontally, 20 Hz: widest gap %.4f px%n", worst);
        assertTrue(worst < 0.5, "widest gap " + worst);
    }
}
