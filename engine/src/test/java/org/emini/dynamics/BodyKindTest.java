package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The broadphase keeps static and dynamic bodies apart (two trees): a body that changes kind must
 * still meet the bodies it should, and the fast-body sweep must still see what it needs.
 */
class BodyKindTest {

    private static World zeroGravityWorld() {
        World world = new World();
        world.setGravity(0f, 0f);
        world.setTicksPerSecond(20f);
        return world;
    }

    @Test
    void staticBodyMadeDynamicFallsOntoTheGround() {
        World world = new World();
        world.addBody(new Body(0f, 20f, Shape.createRectangle(400f, 40f), false));
        Body box = new Body(0f, -100f, Shape.createRectangle(20f, 20f), false);
        world.addBody(box);
        for (int t = 0; t < 20; t++) {
            world.tick();
        }
        assertEquals(-100f, box.getY(), "static: does not fall");
        box.setDynamic(true);
        for (int t = 0; t < 100; t++) {
            world.tick();
        }
        // Resting on the ground's top face (y = 0): centre 10 px above it.
        assertEquals(-10f, box.getY(), 0.5f);
    }

    @Test
    void dynamicBodyMadeStaticHoldsAnother() {
        World world = new World();
        Body shelf = new Body(0f, 20f, Shape.createRectangle(400f, 40f), true);
        world.addBody(shelf);
        Body box = new Body(0f, -30f, Shape.createRectangle(20f, 20f), true);
        world.addBody(box);
        world.tick();
        shelf.setDynamic(false);
        float top = shelf.getY() - 20f;
        for (int t = 0; t < 100; t++) {
            world.tick();
        }
        assertEquals(top + 20f, shelf.getY(), "the shelf stays where it was made static");
        assertEquals(top - 10f, box.getY(), 0.5f);
    }

    /** A fast ball shot at a thin wall that was made static after it was added. */
    @Test
    void fastBallStopsAtAWallMadeStatic() {
        int crossed = 0;
        for (int k = 0; k < 32; k++) {
            World world = zeroGravityWorld();
            Body wall = new Body(1f, 0f, Shape.createRectangle(2f, 400f), true);
            world.addBody(wall);
            world.tick();
            wall.setDynamic(false);
            float travel = 20000f / 20f;
            Body ball = new Body(-40f - travel * (3f + k / 32f), 0f, Shape.createCircle(2.5f), true);
            ball.setVelocity(20000f, 0f);
            world.addBody(ball);
            for (int t = 0; t < 10; t++) {
                world.tick();
            }
            if (ball.getX() > 1f) {
                crossed++;
            }
        }
        assertEquals(0, crossed);
    }

    /**
     * Bullets are swept against dynamic bodies too: a fast-spinning bullet rod does not pass
     * through a free thin plate (an ordinary rod does, as the sweep checks it against static
     * bodies and the landscape only).
     */
    @ParameterizedTest
    @CsvSource({"50, 20, 60", "50, 60, 60", "30, 20, 90", "100, 20, 60"})
    void spinningBulletDoesNotPassThroughADynamicPlate(float spin, int tps, float distance) {
        int crossed = spinningRodsThrough(spin, tps, distance, true, new Body(1f, 0f, Shape.createRectangle(2f, 600f), true));
        assertEquals(0, crossed, "bullet rod spinning at " + spin + " rad/s");
    }

    /**
     * Spins 32 rods 200 px long, at 32 starting angles clear of a plate, about centres {@code distance}
     * left of it for two seconds, each in a world of its own with a copy of the plate (velocity
     * included); returns how many reached past the plate's far face.
     */
    static int spinningRodsThrough(float spin, int tps, float distance, boolean bullet, Body plateModel) {
        int crossed = 0;
        for (int k = 0; k < 32; k++) {
            World world = new World();
            world.setGravity(0f, 0f);
            world.setTicksPerSecond(tps);
            Body plate = new Body(plateModel);
            world.addBody(plate);
            Body rod = new Body(-distance, 0f, Shape.createRectangle(200f, 4f), true);
            float clear = (float) Math.acos((distance - 4f) / 100f);
            rod.setAngle(clear + (float) (Math.PI - 2 * clear) * k / 32);
            rod.setAngularVelocity(spin);
            rod.setBullet(bullet);
            world.addBody(rod);
            for (int t = 0; t < 2 * tps; t++) {
                world.tick();
                // A corner of the rod beyond the plate's far face.
                float reach = rod.getX() + 100f * Math.abs(rod.getCos()) + 2f * Math.abs(rod.getSin());
                if (reach > plate.getX() + 1.5f) {
                    crossed++;
                    break;
                }
            }
        }
        return crossed;
    }
}
