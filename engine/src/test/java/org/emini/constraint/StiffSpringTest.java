package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.ExternalForce;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * Springs far too stiff for the timestep stay bounded: an explicit spring force is unstable once
 * ω·dt &gt; 2; the soft-constraint spring is stable at any ω·dt.
 */
class StiffSpringTest {
    private static final float REST = 50f;
    private static final float STRETCH = 10f;
    private static final float MASS = 2f;

    private static Body disc(World world, float x, float y) {
        Shape s = Shape.createCircle(5f);
        s.setMass(MASS);
        Body b = new Body(x, y, s, true);
        world.addBody(b);
        return b;
    }

    /** The coefficient whose ω = √(k/m) times the timestep is the given value. */
    private static float stiffness(World world, double omegaDt) {
        double omega = omegaDt / world.getTimestep();
        return (float) (MASS * omega * omega);
    }

    @Test
    void springHundredTimesTooStiffForTheTimestepStaysBounded() {
        World world = Rigs.world(20f, 10);
        world.setGravity(0f, 0f);
        Body anchor = Rigs.anchor(world, 0f, 0f);
        Body mass = disc(world, REST + STRETCH, 0f);
        Spring spring = new Spring(anchor, mass, 0f, 0f, 0f, 0f, REST);
        // ω·dt = 200: a hundred times the explicit stability limit of 2.
        spring.setCoefficient(stiffness(world, 200.0));
        world.addConstraint(spring);
        double worst = 0.0;
        for (int t = 0; t < 200; t++) {
            world.tick();
            worst = Math.max(worst, Math.abs(spring.getLength() - REST));
        }
        System.out.printf("spring with ω·dt = 200 (k = %.3g): largest stretch after a tick %.5f px of %.0f, at the end %.2e px%n",
            spring.getCoefficient(), worst, STRETCH, Math.abs(spring.getLength() - REST));
        assertTrue(worst <= STRETCH, "stretch grew to " + worst);
        assertEquals(REST, spring.getLength(), 0.01);
    }

    @Test
    void theSameSpringAsAnExplicitForceBlowsUp() {
        // The original engine's way: F = k·(d − d₀) applied once per tick. With ω·dt = 200 the error
        // grows by about (ω·dt)² per tick until the numbers overflow.
        World world = Rigs.world(20f, 10);
        world.setGravity(0f, 0f);
        Body mass = disc(world, REST + STRETCH, 0f);
        float k = stiffness(world, 200.0);
        world.addExternalForce(new ExternalForce() {
            @Override
            public void applyForce(World w, float timestep) {
                mass.applyForce(-k * (mass.getX() - REST), 0f);
            }
        });
        double largest = 0.0;
        try {
            for (int t = 0; t < 10 && largest < 1e6; t++) {
                world.tick();
                largest = Math.max(largest, Math.abs(mass.getX() - REST));
            }
        } catch (IllegalArgumentException | IllegalStateException overflow) {
            largest = Double.POSITIVE_INFINITY;
        }
        assertTrue(largest >= 1e6, "explicit spring stayed within " + largest);
    }

    @Test
    void stiffSpringsBetweenTwoTurningBodiesUnderGravityStayBounded() {
        // Off-centre anchors couple the spring to rotation; gravity loads it.
        World world = Rigs.world(20f, 10);
        Body anchor = Rigs.anchor(world, 0f, 0f);
        Shape box = Shape.createRectangle(20f, 10f);
        Body a = new Body(0f, 40f, box, true);
        Body b = new Body(15f, 80f, box, true);
        world.addBody(a);
        world.addBody(b);
        float k = 1e8f;
        Spring top = new Spring(anchor, a, 0f, 0f, -8f, -3f);
        Spring link = new Spring(a, b, 8f, 3f, -8f, -3f, 30f);
        top.setCoefficient(k);
        link.setCoefficient(k);
        world.addConstraint(top);
        world.addConstraint(link);
        double worst = 0.0;
        for (int t = 0; t < 400; t++) {
            world.tick();
            worst = Math.max(worst, Math.max(Math.abs(top.getLength() - top.getRestLength()),
                Math.abs(link.getLength() - link.getRestLength())));
            assertTrue(Math.abs(b.getY()) < 1000f && Math.abs(b.getVelocityY()) < 1e4f, "tick " + t);
        }
        System.out.printf("two bodies on k = 1e8 springs under gravity: largest stretch %.4f px%n", worst);
        assertTrue(worst < 15f, "stretch " + worst);
    }

    @Test
    void amplitudeNeverGrowsAtAnyStiffness() {
        for (double omegaDt : new double[] {0.1, 0.5, 1, 2, 5, 10, 20, 50, 200, 2000, 20000}) {
            World world = Rigs.world(20f, 10);
            world.setGravity(0f, 0f);
            Body anchor = Rigs.anchor(world, 0f, 0f);
            Body mass = disc(world, REST + STRETCH, 0f);
            Spring spring = new Spring(anchor, mass, 0f, 0f, 0f, 0f, REST);
            spring.setCoefficient(stiffness(world, omegaDt));
            world.addConstraint(spring);
            double worst = 0.0;
            double late = 0.0;
            for (int t = 0; t < 400; t++) {
                world.tick();
                double x = Math.abs(spring.getLength() - REST);
                worst = Math.max(worst, x);
                if (t >= 300) {
                    late = Math.max(late, x);
                }
            }
            System.out.printf("ω·dt %8.1f: largest stretch %.4f px, in the last 100 ticks %.4f px (start %.0f)%n",
                omegaDt, worst, late, STRETCH);
            assertTrue(worst <= 1.001 * STRETCH, "ω·dt " + omegaDt + ": stretch grew to " + worst);
        }
    }
}
