package org.emini.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.emini.constraint.Motor;
import org.emini.dynamics.Body;
import org.emini.event.Event;
import org.emini.io.PhyBody;
import org.emini.io.PhyMotor;
import org.emini.io.PhyShape;
import org.emini.io.PhyVector;
import org.emini.io.PhyWorld;
import org.emini.io.PhyWriter;
import org.emini.io.WorldBuilder;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * The differences from the original engine that PORTING.md keeps on purpose, pinned: if one of
 * these tests fails, the engine changed a convention and PORTING.md must change with it.
 */
class PortingDifferencesTest {
    @Test
    void positiveAngularVelocityGrowsTheAngleClockwiseOnTheScreen() {
        World w = new World();
        w.setGravity(0);
        Body bar = new Body(0, 0, Shape.createRectangle(40, 4), true);
        bar.setAngularVelocity(1f);
        w.addBody(bar);
        for (int t = 0; t < 20; t++) {
            w.tick();
        }
        assertEquals(1f, bar.getAngle(), 1e-4f, "angle += ω·dt (the original: angle −= ω·dt)");
        // The bar's right end moved down the screen (+y): clockwise on a y-down screen.
        assertTrue(bar.toWorldY(20, 0) > 0f);
    }

    @Test
    void aLoadedWorldsAngularVelocitiesAndRotationalMotorTargetsAreNegated() throws IOException {
        PhyWorld doc = new PhyWorld();
        doc.getShapes().add(new PhyShape(PhyVector.of(-10, -10), PhyVector.of(-10, 10), PhyVector.of(10, 10), PhyVector.of(10, -10)));
        PhyBody body = new PhyBody();
        body.setFlags(PhyBody.FLAG_DYNAMIC | PhyBody.FLAG_ROTATES);
        body.setAngularVelocityRaw(1 << 24);
        doc.getBodies().add(body);
        PhyMotor motor = new PhyMotor();
        motor.setFlags(PhyMotor.FLAG_ROTATIONAL);
        motor.setTargetARaw(2 << 24);
        motor.setMaxForceRaw(5 << 12);
        doc.getConstraints().add(motor);
        World w = WorldBuilder.loadWorld(new ByteArrayInputStream(new PhyWriter().write(doc)), null).getWorld();
        assertEquals(-1f, w.getBody(0).getAngularVelocity(), 1e-6f);
        Motor m = (Motor) w.getConstraint(0);
        assertEquals(-2f, m.getTargetAngularVelocity(), 1e-6f);
        // The original clamps the impulse of a tick (5); the engine's cap is a torque: 5 / (1/20 s).
        assertEquals(100f, m.getMaxForce(), 1e-3f);
    }

    @Test
    void aMotorsCapIsAForceNotAnImpulsePerTick() {
        World w = new World();
        w.setGravity(0);
        Body cart = new Body(0, 0, Shape.createRectangle(20, 20), true);
        w.addBody(cart);
        w.addConstraint(new Motor(cart, 1000f, 0f, 100f));
        for (int t = 0; t < 20; t++) {
            w.tick();
        }
        // 100 force units on mass 1 for 1 s: 100 px/s, whatever the tick rate (the original's cap of
        // 100 would allow 100 px/s of change in every tick).
        assertEquals(100f, cart.getVelocityX(), 0.01f);
    }

    @Test
    void relativeCollisionAnglesPointFromTheBodyToTheContact() {
        World w = new World();
        w.addBody(new Body(0, 20, Shape.createRectangle(200, 20), false));
        Body box = new Body(0, -0.5f, Shape.createRectangle(20, 20), true);
        w.addBody(box);
        float quarter = (float) Math.PI / 2;
        // The contact points are the box's lower corners, at π/4 and 3π/4 from its centre.
        float half = quarter / 2 + 0.1f;
        Event below = Event.createRelativeCollisionEvent(box, null, quarter - half, quarter + half);
        Event above = Event.createRelativeCollisionEvent(box, null, -quarter - half, -quarter + half);
        w.addEvent(below);
        w.addEvent(above);
        List<Event> fired = new ArrayList<>();
        w.setPhysicsEventListener((event, parameter) -> fired.add(event));
        for (int t = 0; t < 5; t++) {
            w.tick();
        }
        // The ground touches the box below it: +π/2 from the body to the points. The original
        // measures from the point to the body, so its range for this contact is centred on −π/2.
        assertTrue(fired.contains(below), fired.toString());
        assertTrue(!fired.contains(above), fired.toString());
    }

    @Test
    void eventsFireInTheOrderTheyWereAdded() {
        World w = new World();
        Body ball = new Body(0, 0, Shape.createCircle(5), true);
        w.addBody(ball);
        for (int i = 0; i < 3; i++) {
            Event e = Event.createPositionEvent(ball, null, -100, -100, 100, 100);
            e.setUserData(i);
            w.addEvent(e);
        }
        List<Object> order = new ArrayList<>();
        w.setPhysicsEventListener((event, parameter) -> order.add(event.getUserData()));
        w.tick();
        assertEquals(List.of(0, 1, 2), order, "registration order (the original: reverse, 2, 1, 0)");
    }
}
