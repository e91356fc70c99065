package org.emini.constraint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.SolverStep;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * An application's own constraint (the manual's "implementing the interface constraint") takes
 * part in the solver like the built-in ones: here a rail that keeps a body's centre on a horizontal
 * line, written only against the public {@link Constraint} and {@link SolverStep} API.
 */
class CustomConstraintTest {
    /** Keeps a body's y at a fixed value; it slides freely along x. */
    static final class Rail implements Constraint {
        private final Body body;
        private final float y;
        private int index;
        private float mass;
        private float impulse;
        private float impulseSubstep;
        // Every impulse applied in the tick, for getForce().
        private float tick;
        private float force;

        Rail(Body body, float y) {
            this.body = body;
            this.y = y;
        }

        @Override
        public boolean concernsBody(Body b) {
            return b == body;
        }

        @Override
        public void prepare(SolverStep step) {
            index = step.indexOf(body);
            float im = step.getInverseMass(index);
            mass = im > 0f ? 1f / im : 0f;
            tick = 0f;
        }

        @Override
        public void warmStart(SolverStep step) {
            float h = step.getSubstep();
            if (impulseSubstep != 0f) {
                impulse *= h / impulseSubstep;
            }
            impulseSubstep = h;
            step.applyImpulse(index, 0f, impulse, 0f, 0f);
            tick += impulse;
        }

        @Override
        public float solve(SolverStep step, boolean useBias) {
            float bias = useBias ? step.getJointBiasRate() * (step.getPositionY(body) - y) : 0f;
            float massScale = useBias ? step.getJointMassScale() : 1f;
            float impulseScale = useBias ? step.getJointImpulseScale() : 0f;
            float d = -massScale * mass * (step.getVelocityY(index) + bias) - impulseScale * impulse;
            impulse += d;
            step.applyImpulse(index, 0f, d, 0f, 0f);
            tick += d;
            return mass > 0f ? Math.abs(d) / mass : 0f;
        }

        @Override
        public void finish(SolverStep step) {
            force = Math.abs(tick) / step.getTimestep();
        }

        @Override
        public float getForce() {
            return force;
        }
    }

    @Test
    void cartOnARailCarriesItsWeightAndSlidesFreely() {
        World world = Rigs.world(20f, 10);
        Shape cartShape = Shape.createRectangle(30f, 10f);
        cartShape.setMass(2f);
        Body cart = new Body(0f, 0f, cartShape, true);
        world.addBody(cart);
        Rail rail = new Rail(cart, 0f);
        world.addConstraint(rail);
        cart.setVelocity(25f, 0f);
        Rigs.run(world, 40);
        assertEquals(0f, cart.getY(), 0.01f);
        assertEquals(50f, cart.getX(), 0.01f);
        assertEquals(2f * world.getGravityY(), rail.getForce(), 0.01f * 200f);
    }

    @Test
    void pendulumOnAFreeCartSwingsWithTheCoupledFrequency() {
        // A point bob m on a rigid rod below a cart M that slides on the rail:
        // ω² = g·(M + m)/(M·L) for small swings, and the horizontal momentum stays 0.
        World world = Rigs.world(60f, 10);
        float bigM = 2f;
        float m = 1f;
        float length = 100f;
        float angle = 0.1f;
        float bobX = length * (float) Math.sin(angle);
        Shape cartShape = Shape.createRectangle(30f, 10f);
        cartShape.setMass(bigM);
        // Centre of mass above the origin, at rest.
        Body cart = new Body(-m * bobX / bigM, 0f, cartShape, true);
        cart.setRotatable(false);
        Shape bobShape = Shape.createCircle(5f);
        bobShape.setMass(m);
        Body bob = new Body(cart.getX() + bobX, length * (float) Math.cos(angle), bobShape, true);
        bob.setRotatable(false);
        world.addBody(cart);
        world.addBody(bob);
        world.addConstraint(new Rail(cart, 0f));
        world.addConstraint(new Spring(cart, bob, 0f, 0f, 0f, 0f));

        double g = world.getGravityY();
        double period = 2 * Math.PI / Math.sqrt(g * (bigM + m) / (bigM * length));
        double dt = world.getTimestep();
        double previous = bob.getX() - cart.getX();
        double first = -1;
        double last = -1;
        int crossings = 0;
        double worstMomentum = 0.0;
        for (int i = 1; i <= (int) (10.3 * period / dt); i++) {
            world.tick();
            double rel = bob.getX() - cart.getX();
            if (previous > 0 && rel <= 0) {
                double t = (i - 1 + previous / (previous - rel)) * dt;
                if (first < 0) {
                    first = t;
                }
                last = t;
                crossings++;
            }
            previous = rel;
            worstMomentum = Math.max(worstMomentum, Math.abs(bigM * cart.getVelocityX() + m * bob.getVelocityX()));
        }
        double measured = (last - first) / (crossings - 1);
        System.out.printf("pendulum on a cart on a user-written rail: T %.4f s, closed form %.4f s, error %.3f%%, |p_x| ≤ %.2e%n",
            measured, period, 100 * (measured - period) / period, worstMomentum);
        assertTrue(crossings >= 10);
        assertEquals(period, measured, 0.01 * period);
        assertEquals(0.0, cart.getY(), 0.01);
        assertTrue(worstMomentum < 1e-2, "horizontal momentum " + worstMomentum);
    }

    @Test
    void motorisedCartOnARailPushesABoxAgainstAWall() {
        // The rail, a motor and the contacts solved together: the cart drives into a free box and
        // pushes it to a wall, where both stop.
        World world = Rigs.world(20f, 10);
        world.setGravity(0f, 0f);
        Body wall = new Body(100f, 0f, Shape.createRectangle(10f, 100f), false);
        world.addBody(wall);
        Body cart = new Body(0f, 0f, Shape.createRectangle(20f, 20f), true);
        Body box = new Body(50f, 0f, Shape.createRectangle(20f, 20f), true);
        world.addBody(cart);
        world.addBody(box);
        Rail rail = new Rail(cart, 0f);
        world.addConstraint(rail);
        Motor motor = new Motor(cart, 40f, 0f, 30f);
        world.addConstraint(motor);
        Rigs.run(world, 80);
        // The rail's force swings from tick to tick (0.07 to 1.75 in the last ticks): its mean.
        float railForce = 0f;
        for (int t = 0; t < 20; t++) {
            world.tick();
            railForce += rail.getForce() / 20f;
        }
        // The box rests against the wall (its face at 95) and the cart against the box, with the
        // motor pressing at its full force and nothing moving.
        assertEquals(85f, box.getX(), 0.2f);
        assertEquals(65f, cart.getX(), 0.3f);
        assertEquals(0f, cart.getY(), 0.01f);
        assertEquals(0f, cart.getVelocityX(), 0.01f);
        assertEquals(30f, motor.getForce(), 0.01f);
        // Weightless: the rail only takes what friction passes on sideways, a small part of it.
        assertTrue(railForce < 2f, "mean rail force " + railForce);
    }
}
