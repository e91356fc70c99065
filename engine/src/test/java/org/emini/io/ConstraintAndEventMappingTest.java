package org.emini.io;

import static org.emini.io.Squares.square;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.emini.constraint.Joint;
import org.emini.constraint.Motor;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.event.Event;
import org.junit.jupiter.api.Test;

/** Joints, springs, motors and events of a world file: the original's conventions mapped. */
class ConstraintAndEventMappingTest {
    /** A static ground box at y = 100 (top face at y = 80) and a dynamic 20 px box at (x, y). */
    private static PhyWorld ground(float x, float y) {
        PhyWorld w = new PhyWorld();
        w.getShapes().add(square(20));
        w.getShapes().add(square(10));
        PhyBody ground = new PhyBody();
        ground.setFlags(PhyBody.FLAG_ROTATES);
        ground.setPosition(PhyVector.of(0, 100));
        w.getBodies().add(ground);
        PhyBody box = new PhyBody();
        box.setShapeIndex(1);
        box.setPosition(PhyVector.of(x, y));
        w.getBodies().add(box);
        return w;
    }

    /** Runs the world and counts, per event index, the ticks in which it fired. */
    private static int[] fired(BuildResult r, int ticks) {
        World world = r.getWorld();
        int[] count = new int[r.getDocument().getEvents().size()];
        boolean[] thisTick = new boolean[count.length];
        world.setPhysicsEventListener((event, parameter) -> {
            for (int i = 0; i < count.length; i++) {
                if (r.getEvent(i) == event) {
                    thisTick[i] = true;
                }
            }
        });
        for (int t = 0; t < ticks; t++) {
            java.util.Arrays.fill(thisTick, false);
            world.tick();
            for (int i = 0; i < count.length; i++) {
                count[i] += thisTick[i] ? 1 : 0;
            }
        }
        return count;
    }

    private static PhyEvent event(int type, int a, int b, int c, int d) {
        PhyEvent e = new PhyEvent();
        e.setType(type);
        e.setTargetRaw(0, a);
        e.setTargetRaw(1, b);
        e.setTargetRaw(2, c);
        e.setTargetRaw(3, d);
        return e;
    }

    @Test
    void jointsAndSpringsKeepTheirBodyLocalAnchors() {
        PhyWorld doc = ground(0, 40);
        PhyJoint j = new PhyJoint();
        j.setBody1(0);
        j.setAnchor1(PhyVector.of(5, -20));
        j.setBody2(1);
        j.setAnchor2(PhyVector.of(-3, 4));
        j.setFixedByte(2);
        doc.getConstraints().add(j);
        PhySpring s = new PhySpring();
        s.setBody1(0);
        s.setBody2(1);
        s.setRestLengthRaw(50 * 4096);
        s.setCoefficientRaw(3 * 4096);
        doc.getConstraints().add(s);
        PhySpring rod = new PhySpring();
        rod.setBody1(1);
        rod.setBody2(0);
        rod.setRestLengthRaw(60 * 4096);
        rod.setCoefficientRaw(-4096);
        doc.getConstraints().add(rod);
        BuildResult r = new WorldBuilder().build(doc);
        Joint joint = (Joint) r.getConstraint(0);
        assertSame(r.getBody(0), joint.getBodyA());
        assertEquals(5f, joint.getLocalAnchorAX());
        assertEquals(-20f, joint.getLocalAnchorAY());
        assertEquals(-3f, joint.getLocalAnchorBX());
        assertEquals(4f, joint.getLocalAnchorBY());
        assertTrue(joint.isFixed(), "a fixed byte above 0");
        Spring spring = (Spring) r.getConstraint(1);
        assertEquals(50f, spring.getRestLength());
        assertEquals(3f, spring.getCoefficient());
        Spring rigid = (Spring) r.getConstraint(2);
        assertTrue(rigid.isRigid(), "a coefficient ≤ 0 is a rigid link");
        assertEquals(60f, rigid.getRestLength());
        assertEquals(3, r.getWorld().getConstraintCount());
    }

    @Test
    void aRotationalMotorTurnsTheWayTheOriginalDoes() {
        PhyWorld doc = ground(0, 40);
        doc.setSettings(new PhyWorldSettings());
        doc.getSettings().setGravity(PhyVector.ZERO);
        PhyMotor m = new PhyMotor();
        m.setBody(1);
        m.setFlags(PhyMotor.FLAG_ROTATIONAL);
        m.setTargetARaw(2 << 24);
        m.setMaxForceRaw(100 * 4096);
        doc.getConstraints().add(m);
        BuildResult r = new WorldBuilder().build(doc);
        Motor motor = (Motor) r.getConstraint(0);
        assertEquals(-2f, motor.getTargetAngularVelocity(), "the original's +2 rad/s turns counter-clockwise");
        assertEquals(100f / r.getWorld().getTimestep(), motor.getMaxForce(), 1e-3f,
                "the original caps the impulse per tick; the engine the force");
        float start = r.getBody(1).getAngle();
        for (int i = 0; i < 40; i++) {
            r.getWorld().tick();
        }
        assertEquals(-2f, r.getBody(1).getAngularVelocity(), 0.01f);
        assertTrue(r.getBody(1).getAngle() < start, "the angle falls, as the original's angle ← angle − ω·dt");
    }

    @Test
    void aLinearMotorKeepsItsTargetAndModes() {
        PhyWorld doc = ground(0, 40);
        PhyMotor m = new PhyMotor();
        m.setBody(1);
        m.setTargetARaw(30 * 4096);
        m.setTargetBRaw(-4096);
        m.setMaxForceRaw(4096);
        m.setFlags(PhyMotor.FLAG_RELATIVE | PhyMotor.FLAG_FIX_ORTHOGONAL);
        doc.getConstraints().add(m);
        Motor motor = (Motor) new WorldBuilder().build(doc).getConstraint(0);
        assertEquals(30f, motor.getTargetVelocityX());
        assertEquals(-1f, motor.getTargetVelocityY());
        assertTrue(motor.isRelative());
        assertTrue(motor.isOrthogonal());
    }

    @Test
    void aConstraintTheEngineRefusesIsListedAndANegativeRestLengthIsMeasured() {
        PhyWorld doc = ground(0, 40);
        doc.getConstraints().add(new PhyJoint());
        PhySpring negative = new PhySpring();
        negative.setBody2(1);
        negative.setRestLengthRaw(-1);
        doc.getConstraints().add(negative);
        BuildResult r = new WorldBuilder().build(doc);
        assertNull(r.getConstraint(0));
        assertTrue(r.getUnsupported().get(0).getReason().contains("must differ"), r.getUnsupported().toString());
        // A negative rest length is the original's "measure the distance": built, at the anchors' distance.
        assertEquals(1, r.getUnsupported().size(), r.getUnsupported().toString());
        Spring measured = (Spring) r.getConstraint(1);
        assertEquals(measured.getLength(), measured.getRestLength(), 0f);
        assertEquals(1, r.getWorld().getConstraintCount());
    }

    @Test
    void bodyEventsMapTheOriginalsUnits() {
        // The box falls 10 px in the tick, 30 px above the ground: it stays in the air.
        PhyWorld doc = ground(0, 40);
        doc.getBodies().get(1).setAngularVelocityRaw(1 << 24);
        doc.getBodies().get(1).setVelocity(PhyVector.of(0, 200));
        int one = 1 << 24;
        doc.getEvents().add(event(PhyEvent.TYPE_BODY_POSITION, -10 << 12, 50 << 12, 10 << 12, 90 << 12));
        doc.getEvents().add(event(PhyEvent.TYPE_BODY_POSITION, 20 << 12, 50 << 12, 30 << 12, 90 << 12));
        // Squared speeds: 150² and 250² px²/s².
        doc.getEvents().add(event(PhyEvent.TYPE_BODY_VELOCITY, 22500 << 12, 62500 << 12, 0, 0));
        // The original's sign: +0.5..+1.5 rad/s holds for its +1; the engine reads −1.
        doc.getEvents().add(event(PhyEvent.TYPE_BODY_ANGULAR_VELOCITY, one / 2, 3 * one / 2, 0, 0));
        doc.getEvents().add(event(PhyEvent.TYPE_BODY_ANGULAR_VELOCITY, -3 * one / 2, -one / 2, 0, 0));
        doc.getEvents().add(event(PhyEvent.TYPE_BODY_ROTATION, 0, PhyFixed.TWO_PI_2FX, 0, 0));
        for (PhyEvent e : doc.getEvents()) {
            e.setBodyFilter(1);
        }
        int[] fired = fired(new WorldBuilder().build(doc), 1);
        assertEquals(List.of(1, 0, 1, 1, 0, 1), List.of(fired[0], fired[1], fired[2], fired[3], fired[4], fired[5]));
    }

    @Test
    void collisionEventsSeeTheBoxStandingOnTheGround() {
        PhyWorld doc = ground(0, 69);
        doc.getEvents().add(event(PhyEvent.TYPE_BODY_COLLISION, 0, 0, 4096, 0));
        doc.getEvents().add(event(PhyEvent.TYPE_BODY_COLLISION, 4096, 0, 0, 0));
        // The original's direction runs from the contact to the body: up, 3π/2, within 45°.
        doc.getEvents().add(event(PhyEvent.TYPE_BODY_COLLISION_RELATIVE, 3 * PhyFixed.PI_2FX / 2, 2896, 0, 0));
        doc.getEvents().add(event(PhyEvent.TYPE_BODY_COLLISION_RELATIVE, PhyFixed.PI_2FX / 2, 2896, 0, 0));
        for (PhyEvent e : doc.getEvents()) {
            e.setBodyFilter(1);
        }
        int[] fired = fired(new WorldBuilder().build(doc), 20);
        assertTrue(fired[0] > 10, "below: " + fired[0]);
        assertEquals(0, fired[1], "above");
        assertTrue(fired[2] > 10, "relative, up from the contact: " + fired[2]);
        assertEquals(0, fired[3], "relative, down from the contact");
    }

    @Test
    void aSensorEventGetsItsSensorBodyAndUserData() {
        PhyWorld doc = ground(0, 40);
        PhyEvent e = event(PhyEvent.TYPE_BODY_SENSOR, 0, 0, 0, 0);
        PhyBody sensor = new PhyBody();
        sensor.setShapeIndex(0);
        sensor.setPosition(PhyVector.of(0, 40));
        sensor.setFlags(PhyBody.FLAG_ROTATES);
        sensor.setUserData("sensor");
        e.setSensor(sensor);
        e.setUserData("the sensor event");
        e.setTriggerOnceByte(1);
        doc.getEvents().add(e);
        List<String> calls = new ArrayList<>();
        BuildResult r = new WorldBuilder().setUserData((data, type) -> {
            calls.add(type + ":" + data);
            return data;
        }).build(doc);
        Event event = r.getEvent(0);
        assertEquals(Event.SENSOR, event.getType());
        assertTrue(event.isTriggerOnce());
        assertEquals("the sensor event", event.getUserData());
        assertEquals("sensor", event.getSensor().getUserData());
        assertNull(event.getSensor().getWorld(), "the sensor is not part of the world");
        assertEquals(List.of("2:", "2:", "1:", "1:", "3:the sensor event", "1:sensor"), calls);
        assertEquals(1, fired(r, 3)[0], "trigger once: the dynamic box is reported once");
    }

    @Test
    void eventFiltersNameTheBuiltObjects() {
        PhyWorld doc = ground(0, 40);
        PhyJoint j = new PhyJoint();
        j.setBody2(1);
        doc.getConstraints().add(j);
        PhyEvent force = event(PhyEvent.TYPE_CONSTRAINT_FORCE, 0, 4096, 0, 0);
        force.setConstraintFilter(0);
        doc.getEvents().add(force);
        PhyEvent shaped = event(PhyEvent.TYPE_BODY_POSITION, 0, 0, 0, 0);
        shaped.setShapeFilter(1);
        doc.getEvents().add(shaped);
        PhyEvent unknown = event(77, 0, 0, 0, 0);
        doc.getEvents().add(unknown);
        PhyEvent backwards = event(PhyEvent.TYPE_BODY_POSITION, 10, 0, 0, 0);
        doc.getEvents().add(backwards);
        BuildResult r = new WorldBuilder().build(doc);
        assertSame(r.getConstraint(0), r.getEvent(0).getConstraint());
        assertEquals(UnsupportedElement.Kind.EVENT, r.getApproximations().get(0).getKind());
        assertSame(r.getShape(1), r.getEvent(1).getShape());
        assertNull(r.getEvent(2));
        assertEquals("event 2: event type 77 is not defined", r.getUnsupported().get(0).toString());
        assertNull(r.getEvent(3), "min x above max x");
        assertEquals(2, r.getWorld().getEventCount());
    }

    @Test
    void anEventOnARecordThatIsNotBuiltIsListedRatherThanWidened() {
        PhyWorld doc = ground(0, 40);
        doc.getShapes().add(new PhyShape(PhyVector.of(0.2f, 0)));
        PhyBody tiny = new PhyBody();
        tiny.setShapeIndex(2);
        doc.getBodies().add(tiny);
        PhyEvent e = event(PhyEvent.TYPE_BODY_POSITION, 0, 0, 0, 0);
        e.setBodyFilter(2);
        doc.getEvents().add(e);
        BuildResult r = new WorldBuilder().build(doc);
        assertNull(r.getEvent(0));
        assertEquals("event 0: its body 2 is not built", r.getUnsupported().get(2).toString());
        Body built = r.getBody(1);
        assertTrue(built != null);
    }
}
