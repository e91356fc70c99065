package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Joints that fight each other (over-constrained: they cannot all be satisfied) settle into a
 * compromise and stay there, velocities bounded and energy not growing. The scene is the world
 * fuzzer's minimal case (issue 14): two pins from a wall to a 12 px circle, at points 14 px and
 * 171 px from its centre that are 10 px too far apart to both hold. Their stress, thousands of
 * times the circle's weight, was warm-started on arms the circle had turned, as a torque that
 * grew each substep: the circle was flung to infinity within 7 ticks (it held with the joint
 * stiffness lowered to 5 Hz, or without warm starting).
 */
class FightingJointsTest {
    private static final int TICKS = 2000;
    /** Ticks the fight is given to settle before the energy is watched. */
    private static final int SETTLE = 200;

    @ParameterizedTest(name = "{0}, dynamic iterations {1}")
    @CsvSource({
        "two loose pins, false",
        "two loose pins, true",
        "three loose pins, false",
        "a loose and a fixed pin, false",
        "two fixed pins, false",
    })
    void fightingJointsSettleWithBoundedVelocitiesAndNoEnergyGain(String rig, boolean dynamicIterations) {
        World world = new World();
        world.setConstraintIterationDynamic(dynamicIterations);
        Body wall = new Body(-260.25f, -250f, Shape.createRectangle(20f, 500f), false);
        Shape disc = Shape.createCircle(12.375f);
        disc.setMass(94.0625f);
        Body circle = new Body(82.4375f, -221.625f, disc, true);
        circle.setAngle(-0.2578125f);
        world.addBody(wall);
        world.addBody(circle);
        boolean secondFixed = rig.contains("fixed");
        world.addConstraint(new Joint(wall, circle, 342.6875f, 28.375f, -12.8125f, 6.75f, rig.startsWith("two fixed")));
        world.addConstraint(Joint.atWorldPoint(wall, circle, -88.875f, -235.8125f, secondFixed));
        if (rig.startsWith("three")) {
            // 18 px from where it holds, 80 px from the centre.
            world.addConstraint(new Joint(wall, circle, 355f, 104f, 10f, 80f, false));
        }

        float cap = world.getSolverSettings().getJointPushMaxVelocity();
        float dt = world.getTimestep();
        double fastest = 0.0;
        double lateFastest = 0.0;
        double settledEnergy = 0.0;
        double energyRise = 0.0;
        float x = circle.getX();
        float y = circle.getY();
        for (int t = 0; t < TICKS; t++) {
            world.tick();
            // The speed from the velocity and from the motion in the tick (a fight can move a body
            // through its position correction while its velocity stays near zero).
            double moved = Math.hypot(circle.getX() - x, circle.getY() - y) / dt;
            double speed = Math.max(moved, Math.hypot(circle.getVelocityX(), circle.getVelocityY()));
            double spin = Math.abs(circle.getAngularVelocity());
            x = circle.getX();
            y = circle.getY();
            fastest = Math.max(fastest, speed);
            if (t >= TICKS - 100) {
                lateFastest = Math.max(lateFastest, speed + spin * 12.375);
            }
            // Gravity pulls down the screen (+y): potential energy −m·g·y.
            double energy = circle.getKineticEnergy() - circle.getMass() * world.getGravityY() * circle.getY();
            if (t == SETTLE) {
                settledEnergy = energy;
            } else if (t > SETTLE) {
                energyRise = Math.max(energyRise, energy - settledEnergy);
            }
        }
        double weight = circle.getMass() * world.getGravityY();
        System.out.printf("fighting joints, %s%s: fastest %.1f px/s, last 100 ticks ≤ %.2g px/s, energy rise %.3g "
            + "(the weight lifted by %.2g px)%n", rig, dynamicIterations ? ", dynamic iterations" : "", fastest,
            lateFastest, energyRise, energyRise / weight);
        // The joints pull toward the compromise no faster than their push cap (the circle is small:
        // its centre moves with its anchors).
        assertTrue(fastest < cap, "fastest " + fastest + " px/s, cap " + cap);
        assertTrue(lateFastest < 0.1, "still moving at " + lateFastest + " px/s after " + TICKS + " ticks");
        // Settled, the fight creates no energy: less than lifting the circle by a hundredth of a pixel.
        assertTrue(energyRise < 0.01 * weight, "energy rose by " + energyRise);
    }
}
