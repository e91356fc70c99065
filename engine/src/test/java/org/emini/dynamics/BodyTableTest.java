package org.emini.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/** The world's body list against a plain list: order kept, ids found, through random adds, removals and ticks. */
class BodyTableTest {
    @Test
    void randomAddsAndRemovalsKeepTheOrderAndFindEveryId() {
        Random random = new Random(5);
        World world = new World();
        List<Body> expected = new ArrayList<>();
        Shape shape = Shape.createCircle(3f);
        List<Body> removed = new ArrayList<>();
        for (int step = 0; step < 3000; step++) {
            int op = random.nextInt(10);
            if (op < 5 || expected.isEmpty()) {
                Body b = new Body(random.nextFloat() * 1000f, random.nextFloat() * 1000f, shape, random.nextBoolean());
                world.addBody(b);
                expected.add(b);
            } else if (op < 9) {
                Body b = expected.remove(random.nextInt(expected.size()));
                assertEquals(true, world.removeBody(b));
                removed.add(b);
            } else {
                world.tick();
            }
            if (step % 97 == 0) {
                assertEquals(expected.size(), world.getBodyCount());
                for (int i = 0; i < expected.size(); i++) {
                    assertSame(expected.get(i), world.getBody(i), "index " + i);
                    assertSame(expected.get(i), world.findBodyById(expected.get(i).getId()));
                }
            }
        }
        for (Body b : removed) {
            assertNull(world.findBodyById(b.getId()));
        }
    }
}
