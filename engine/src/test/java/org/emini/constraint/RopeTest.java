package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A rope (a distance joint with range [0, L]): a ball released with the rope taut and horizontal
 * swings without the rope ever growing past L (by more than 0.02 px, the joint softness under
 * 3·m·g); released 60 px below the ceiling on a 100 px rope it
 * falls freely (no tension) until the rope goes taut.
 */
class RopeTest {
    private static final float LENGTH = 100f;

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void tautRopeNeverExceedsItsLengthInASwing(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        Body ceiling = Rigs.anchor(world, 0f, 0f);
        Body ball = new Body(LENGTH, 0f, Shape.createCircle(5f), true);
        world.addBody(ball);
        DistanceJoint rope = DistanceJoint.rope(ceiling, ball, 0f, 0f, 0f, 0f, LENGTH);
        world.addConstraint(rope);
        double longest = 0.0;
        double lowest = 0.0;
        double tension = 0.0;
        for (int i = 0; i < 10 * ticksPerSecond; i++) {
            world.tick();
            longest = Math.max(longest, rope.getCurrentLength());
            lowest = Math.max(lowest, ball.getY());
            tension = Math.max(tension, rope.getTension());
        }
        double weight = ball.getMass() * world.getGravityY();
        System.out.printf("rope %.0f ticks/s: longest %.5f px (length %.0f), lowest %.3f px, peak tension %.3f m·g"
            + " (closed form 3)%n", ticksPerSecond, longest, LENGTH, lowest, tension / weight);
        assertTrue(longest <= LENGTH + 0.02, "stretched to " + longest);
        // A taut pendulum released at 90°: 3·m·g at the bottom, and it reaches the full length below the ceiling.
        assertEquals(3.0, tension / weight, 0.03);
        assertEquals(LENGTH, lowest, 0.1);
    }

    @ParameterizedTest(name = "{0} ticks/s")
    @ValueSource(floats = {20f, 60f})
    void slackRopeLetsTheBallFallFreely(float ticksPerSecond) {
        World world = Rigs.world(ticksPerSecond, 10);
        Body ceiling = Rigs.anchor(world, 0f, 0f);
        Body ball = new Body(0f, 60f, Shape.createCircle(5f), true);
        world.addBody(ball);
        DistanceJoint rope = DistanceJoint.rope(ceiling, ball, 0f, 0f, 0f, 0f, LENGTH);
        world.addConstraint(rope);
        double g = world.getGravityY();
        double h = world.getTimestep() / world.getConstraintIterations();
        // Free fall from 60 px covers the 40 px of slack after √(2·40/g) ≈ 0.894 s: check at 0.8 s.
        int ticks = (int) Math.round(0.8f * ticksPerSecond);
        Rigs.run(world, ticks);
        double t = ticks * world.getTimestep();
        assertEquals(60.0 + 0.5 * g * t * (t + h), ball.getY(), 1e-3);
        assertEquals(0.0, rope.getTension(), 0.0);
        Rigs.run(world, (int) Math.round(2f * ticksPerSecond));
        System.out.printf("rope slack %.0f ticks/s: length after it went taut %.4f px%n", ticksPerSecond,
            rope.getCurrentLength());
        assertTrue(rope.getCurrentLength() <= LENGTH + 0.01, "stretched to " + rope.getCurrentLength());
    }
}
