package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/**
 * {@link World#queryBodies} finds exactly the bodies whose box overlaps a rectangle where they are
 * now, in world order: simulated bodies the solver moved, frozen and static ones, and bodies the
 * application moved since the last tick.
 */
class QueryBodiesTest {
    private static List<Integer> query(World world, float minX, float minY, float maxX, float maxY) {
        List<Integer> found = new ArrayList<>();
        world.queryBodies(minX, minY, maxX, maxY, index -> found.add(index) || true);
        return found;
    }

    private static List<Integer> bruteForce(World world, float minX, float minY, float maxX, float maxY) {
        List<Integer> found = new ArrayList<>();
        float[] box = new float[4];
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            b.getShape().computeAabb(b.getX(), b.getY(), b.getCos(), b.getSin(), box);
            if (box[0] <= maxX && minX <= box[2] && box[1] <= maxY && minY <= box[3]) {
                found.add(i);
            }
        }
        return found;
    }

    private static void assertExact(World world, Random random) {
        for (int q = 0; q < 20; q++) {
            float x = -700f + 1400f * random.nextFloat();
            float y = -500f + 700f * random.nextFloat();
            float w = 300f * random.nextFloat();
            float h = 300f * random.nextFloat();
            assertEquals(bruteForce(world, x, y, x + w, y + h), query(world, x, y, x + w, y + h));
        }
    }

    @Test
    void findsExactlyTheBodiesOverlappingARectangleWhereTheyAreNow() {
        World world = new World();
        world.addBody(new Body(0f, 100f, Shape.createRectangle(1400f, 20f), false));
        Random random = new Random(14);
        for (int i = 0; i < 150; i++) {
            Shape shape = i % 2 == 0 ? Shape.createCircle(4f + 6f * random.nextFloat())
                : Shape.createRectangle(5f + 20f * random.nextFloat(), 5f + 20f * random.nextFloat());
            Body b = new Body(-650f + 1300f * random.nextFloat(), -400f * random.nextFloat(), shape, i % 7 != 0);
            float vx = 200f * random.nextFloat() - 100f;
            // A static body refuses a velocity.
            if (b.isDynamic()) {
                b.setVelocity(vx, 0f);
            }
            world.addBody(b);
        }
        assertExact(world, random);
        for (int t = 0; t < 120; t++) {
            float x = -700f + 10f * t;
            world.setSimulationArea(x, -1000f, x + 400f, 1000f);
            world.tick();
            assertExact(world, random);
            if (t % 10 == 0) {
                // Moved by the application: a frozen or static body, and one of the simulated.
                world.getBody(1 + random.nextInt(150)).translate(30f, -20f);
                assertExact(world, random);
            }
        }
    }

    @Test
    void aBodyThrownOutOfTheAreaInItsLastTickIsFoundWhereItFroze() {
        World world = new World();
        world.setGravity(0f, 0f);
        world.setSimulationArea(-100f, -100f, 100f, 100f);
        Body thrown = new Body(0f, 0f, Shape.createRectangle(10f, 10f), true);
        world.addBody(thrown);
        world.tick();
        // A force the broadphase's box cannot foresee: ½·a·dt² = 1,250 px in one tick.
        thrown.applyForce(1e6f, 0f);
        world.tick();
        assertTrue(thrown.getX() > 1000f, "x " + thrown.getX());
        world.tick();
        assertTrue(!thrown.isSimulated());
        float x = thrown.getX();
        assertEquals(List.of(0), query(world, x - 1f, -1f, x + 1f, 1f));
        assertEquals(List.of(), query(world, -1f, -1f, 1f, 1f));
    }

    @Test
    void badRectanglesAreRefusedWithTheCallNamed() {
        World world = new World();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> world.queryBodies(1f, 0f, 0f, 1f, index -> true));
        assertTrue(e.getMessage().contains("World.queryBodies"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> world.queryBodies(Float.NaN, 0f, 1f, 1f, index -> true));
        assertThrows(IllegalArgumentException.class, () -> world.queryBodies(0f, 0f, 1f, 1f, null));
    }
}
