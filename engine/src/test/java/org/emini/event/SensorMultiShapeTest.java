package org.emini.event;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/** Sensor events on multi-shape bodies and multi-shape sensors test each part (no narrowphase of a whole multi-shape). */
class SensorMultiShapeTest {
    @Test
    void aMultiShapeBodyFallingThroughASensorIsReported() {
        World world = new World();
        Body sensor = new Body(0f, 0f, Shape.createRectangle(100f, 20f), false);
        sensor.setInteracting(false);
        world.addBody(sensor);
        Body dumbbell = new Body(0f, -40f, Shape.createMultiShape(Shape.createCircle(5f),
                Shape.createRectangle(20f, 4f)), true);
        world.addBody(dumbbell);
        int[] hits = new int[1];
        world.setPhysicsEventListener((e, p) -> hits[0]++);
        world.addEvent(Event.createSensorEvent(null, null, sensor));
        Rigs.runTicks(world, 20);
        assertTrue(hits[0] > 0, "the dumbbell passed through the sensor unseen");
    }

    @Test
    void aMultiShapeSensorSeesABodyInItsSecondPartOnly() {
        World world = new World();
        world.setGravity(0f, 0f);
        Shape two = Shape.createMultiShape(Shape.createRectangle(10f, 10f), Shape.createPolygon(90f, -5f, 100f, -5f, 100f, 5f, 90f, 5f));
        Body sensor = new Body(0f, 0f, two, false);
        sensor.setInteracting(false);
        world.addBody(sensor);
        Body inGap = new Body(50f, 0f, Shape.createCircle(3f), true);
        Body inSecond = new Body(95f, 0f, Shape.createCircle(3f), true);
        world.addBody(inGap);
        world.addBody(inSecond);
        java.util.List<Object> seen = new java.util.ArrayList<>();
        world.setPhysicsEventListener((e, p) -> seen.add(p));
        world.addEvent(Event.createSensorEvent(null, null, sensor));
        world.tick();
        assertTrue(seen.contains(inSecond) && !seen.contains(inGap), "seen " + seen);
    }
}
