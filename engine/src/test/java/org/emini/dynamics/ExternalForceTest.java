package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.shape.Shape;
import org.emini.world.ExternalForce;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/** External forces act every tick before the solve: buoyancy floats a box at the closed-form depth. */
class ExternalForceTest {
    /**
     * Water below y = 0 with a density (mass per px²): an upward force ρ·g·(submerged area) on
     * upright boxes, and linear drag in the water. Allocation-free, as a force should be.
     */
    static final class Buoyancy implements ExternalForce {
        final float density;
        final float drag;
        private final float[] box = new float[4];

        Buoyancy(float density, float drag) {
            this.density = density;
            this.drag = drag;
        }

        @Override
        public void applyForce(World world, float timestep) {
            float g = world.getGravityY();
            for (int i = 0; i < world.getBodyCount(); i++) {
                Body b = world.getBody(i);
                if (!b.isDynamic()) {
                    continue;
                }
                Shape s = b.getShape();
                float height = s.getArea() / width(s);
                float bottom = b.getY() + 0.5f * height;
                float depth = Math.max(0f, Math.min(height, bottom));
                if (depth > 0f) {
                    b.applyForce(-drag * b.getVelocityX(), -density * g * width(s) * depth - drag * b.getVelocityY());
                }
            }
        }

        /** The width of an upright box: its bounding box's. */
        private float width(Shape s) {
            s.computeAabb(0f, 0f, 1f, 0f, box);
            return box[2] - box[0];
        }
    }

    private static Body box(World world, float y, float mass) {
        Shape s = Shape.createRectangle(40f, 20f);
        s.setMass(mass);
        Body b = new Body(0f, y, s, true);
        b.setRotatable(false);
        world.addBody(b);
        return b;
    }

    @Test
    void boxFloatsAtTheDepthWhereItDisplacesItsOwnMass() {
        World world = new World();
        float density = 0.002f;
        world.addExternalForce(new Buoyancy(density, 2f));
        Body box = box(world, -50f, 1f);
        Scenes.run(world, 30f);
        // ρ·g·w·d = m·g: d = m/(ρ·w) = 12.5 px of its 20.
        float depth = box.getY() + 10f;
        System.out.printf("floating box: depth %.4f px, closed form %.4f px%n", depth, 1f / (density * 40f));
        assertEquals(1f / (density * 40f), depth, 0.05f);
        assertEquals(0f, box.getVelocityY(), 0.01f);
    }

    @Test
    void boxDenserThanWaterSinksAtTheReducedAcceleration() {
        World world = new World();
        world.addExternalForce(new Buoyancy(0.002f, 0f));
        Body box = box(world, 20f, 2f);
        Scenes.run(world, 1f);
        // Fully under: a = g·(1 − ρ·w·h/m) = 100·(1 − 0.002·800/2) = 20 px/s².
        assertEquals(20f, box.getVelocityY(), 1e-3f);
    }

    @Test
    void forceAppliedThisTickMovesTheBodyThisTick() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body body = box(world, 0f, 2f);
        ExternalForce wind = (w, dt) -> {
            for (int i = 0; i < w.getBodyCount(); i++) {
                w.getBody(i).applyForce(10f, 0f);
            }
        };
        world.addExternalForce(wind);
        world.tick();
        assertEquals(5f * world.getTimestep(), body.getVelocityX(), 1e-6f);
        assertSame(wind, world.getExternalForce(0));
        assertEquals(1, world.getExternalForceCount());
        assertThrows(IllegalArgumentException.class, () -> world.addExternalForce(wind));
        assertTrue(world.removeExternalForce(wind));
        assertFalse(world.removeExternalForce(wind));
        world.tick();
        assertEquals(5f * world.getTimestep(), body.getVelocityX(), 1e-6f);
    }
}
