package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/** Rigid springs hold their length both ways; springs with a coefficient settle at Hooke's stretch. */
class SpringStaticsTest {
    private static Body hung(World world, float y, float mass) {
        Shape disc = Shape.createCircle(5f);
        disc.setMass(mass);
        Body b = new Body(0f, y, disc, true);
        world.addBody(b);
        return b;
    }

    @Test
    void rigidSpringPushesOutAndPullsInToItsRestLength() {
        // The original: a link of rest 40 px started at 30 px is pushed out to 40.
        World world = Rigs.world(20f, 10);
        world.setGravity(0f, 0f);
        Body anchor = Rigs.anchor(world, 0f, 0f);
        Body near = hung(world, 30f, 1f);
        Body far = new Body(0f, -50f, Shape.createCircle(5f), true);
        world.addBody(far);
        Spring push = new Spring(anchor, near, 0f, 0f, 0f, 0f, 40f);
        Spring pull = new Spring(anchor, far, 0f, 0f, 0f, 0f, 40f);
        world.addConstraint(push);
        world.addConstraint(pull);
        assertTrue(push.isRigid());
        Rigs.run(world, 20);
        assertEquals(40f, push.getLength(), 0.05f);
        assertEquals(40f, pull.getLength(), 0.05f);
        // Once there it stays: no drift while the bodies are pushed around.
        near.applyImpulse(30f, 0f);
        far.applyImpulse(-30f, 5f);
        double worst = 0.0;
        for (int t = 0; t < 200; t++) {
            world.tick();
            worst = Math.max(worst, Math.max(Math.abs(push.getLength() - 40f), Math.abs(pull.getLength() - 40f)));
        }
        System.out.printf("rigid springs of 40 px, swinging: length error ≤ %.4f px%n", worst);
        assertTrue(worst < 0.1, "length error " + worst);
    }

    @Test
    void rigidSpringDefaultsToTheDistanceAtCreationAndCarriesTheWeight() {
        World world = Rigs.world(20f, 10);
        Body anchor = Rigs.anchor(world, 0f, 0f);
        Body mass = hung(world, 60f, 3f);
        Spring rod = new Spring(anchor, mass, 0f, 2f, 0f, -5f);
        assertEquals(53f, rod.getRestLength(), 1e-4f);
        world.addConstraint(rod);
        Rigs.run(world, 100);
        assertEquals(53f, rod.getLength(), 0.05f);
        assertEquals(3f * world.getGravityY(), rod.getTension(), 0.01f * 300f);
        assertEquals(rod.getTension(), rod.getForce(), 0f);
    }

    @Test
    void hangingMassStretchesTheSpringByWeightOverK() {
        World world = Rigs.world(20f, 10);
        Body anchor = Rigs.anchor(world, 0f, 0f);
        float m = 2f;
        float k = 50f;
        Body mass = hung(world, 100f, m);
        Spring spring = new Spring(anchor, mass, 0f, 0f, 0f, 0f);
        spring.setCoefficient(k);
        // Critical damping 2·√(k·m) settles it quickly.
        spring.setDamping(2f * (float) Math.sqrt(k * m));
        world.addConstraint(spring);
        Rigs.run(world, 400);
        float g = world.getGravityY();
        System.out.printf("mass %.0f on k = %.0f: stretch %.4f px (m·g/k = %.4f), tension %.3f (m·g = %.1f)%n",
            m, k, spring.getLength() - 100f, m * g / k, spring.getTension(), m * g);
        assertEquals(m * g / k, spring.getLength() - 100f, 0.01f * m * g / k);
        assertEquals(m * g, spring.getTension(), 0.01f * m * g);
        assertEquals(0f, mass.getVelocityY(), 0.1f);
    }

    @Test
    void compressedSpringPushesWithNegativeTension() {
        World world = Rigs.world(20f, 10);
        world.setGravity(0f, 0f);
        Body anchor = Rigs.anchor(world, 0f, 0f);
        Body mass = hung(world, 40f, 1f);
        Spring spring = new Spring(anchor, mass, 0f, 0f, 0f, 0f, 50f);
        spring.setCoefficient(10f);
        world.addConstraint(spring);
        world.tick();
        // F = k·(d − d₀) = 10·(40 − 50): pushing, so the tension is about −100 in the first tick.
        assertEquals(-100f, spring.getTension(), 5f);
        assertTrue(mass.getVelocityY() > 0f);
    }
}
