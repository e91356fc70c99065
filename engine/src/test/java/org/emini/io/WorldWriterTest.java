package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.List;
import org.emini.constraint.Joint;
import org.emini.constraint.Motor;
import org.emini.constraint.RevoluteJoint;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Landscape;
import org.emini.event.Event;
import org.emini.shape.MultiShape;
import org.emini.shape.Shape;
import org.emini.world.World;
import org.junit.jupiter.api.Test;

/** Saving a World as an original world file: what it holds comes back when the file is loaded. */
class WorldWriterTest {
    private static World level() {
        World w = new World();
        w.setGravity(5f, 120f);
        w.setDampingLateral(0.02f);
        w.setDampingRotational(0.01f);
        w.setUserData("level one");
        Shape crate = Shape.createRectangle(20, 20);
        crate.setFrictionPercent(60);
        crate.setMass(2);
        crate.setUserData("crate");
        w.getShapeSet().register(crate);
        Shape ball = Shape.createCircle(8);
        ball.setElasticity(0.5f);
        Shape l = new MultiShape(Shape.createPolygon(0, -30, 10, -30, 10, 0, 0, 0), Shape.createPolygon(0, 0, 30, 0, 30, 10, 0, 10))
            .centred();
        Body anchor = new Body(0, -100, Shape.createRectangle(4, 4), false);
        w.addBody(anchor);
        Body a = new Body(-40, 0, crate, true);
        a.setAngle(0.3f);
        a.setAngularVelocity(1.5f);
        a.setUserData("first crate");
        a.addCollisionLayer(3);
        Body b = new Body(-10, 0, crate, true);
        b.setAngle(0.3f);
        Body wheel = new Body(60, 20, ball, true);
        wheel.setGravityAffected(false);
        Body hook = new Body(100, 40, l, true);
        hook.setRotatable(false);
        w.addBody(a);
        w.addBody(b);
        w.addBody(wheel);
        w.addBody(hook);
        Joint weld = Joint.atWorldPoint(a, b, -25, 0, true);
        weld.setUserData("weld");
        w.addConstraint(weld);
        Spring rope = new Spring(anchor, a, 0, 0, 0, 0);
        rope.setCoefficient(40f);
        w.addConstraint(rope);
        w.addConstraint(new Motor(wheel, 2.5f, 400f));
        Motor drive = new Motor(hook, 30f, 0f, 100f);
        drive.setOrthogonal(true);
        w.addConstraint(drive);
        Landscape land = w.getLandscape();
        land.addSegment(-300, 150, 300, 150, Landscape.FACE_LEFT);
        land.addSegment(300, 150, 320, 60);
        land.setFriction(0.4f);
        return w;
    }

    private static World saveAndLoad(World w, WorldWriter writer) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        writer.write(w, bytes);
        BuildResult r = WorldBuilder.loadWorld(new ByteArrayInputStream(bytes.toByteArray()), (data, type) -> data);
        assertEquals(List.of(), r.getUnsupported(), "the saved file loads whole");
        return r.getWorld();
    }

    @Test
    void aSavedWorldLoadsWithItsBodiesConstraintsLandscapeAndSettings() throws IOException {
        World w = level();
        WorldWriter writer = new WorldWriter();
        World back = saveAndLoad(w, writer);
        assertEquals(List.of(), writer.getNotSaved());
        assertEquals(5f, back.getGravityX());
        assertEquals(120f, back.getGravityY());
        assertEquals(0.02f, back.getDampingLateral(), 1f / 4096);
        assertEquals("level one", back.getUserData());
        assertEquals(w.getBodyCount(), back.getBodyCount());
        float fx = 1f / 4096;
        for (int i = 0; i < w.getBodyCount(); i++) {
            Body o = w.getBody(i);
            Body l = back.getBody(i);
            assertEquals(o.getX(), l.getX(), fx, "body " + i);
            assertEquals(o.getY(), l.getY(), fx, "body " + i);
            assertEquals(o.getAngle(), l.getAngle(), 1e-6f, "body " + i);
            assertEquals(o.getAngularVelocity(), l.getAngularVelocity(), 1e-6f, "the sign survives the file's flip: body " + i);
            assertEquals(o.isDynamic(), l.isDynamic());
            assertEquals(o.canRotate(), l.canRotate());
            assertEquals(o.isAffectedByGravity(), l.isAffectedByGravity());
            assertEquals(o.getCollisionLayers(), l.getCollisionLayers());
            assertEquals(o.getShape().getMass(), l.getShape().getMass(), fx);
            assertEquals(o.getShape().getFriction(), l.getShape().getFriction(), fx);
            assertEquals(o.getShape().getElasticity(), l.getShape().getElasticity(), fx);
            assertEquals(o.getShape().getInertia(), l.getShape().getInertia(), 1e-3f * o.getShape().getInertia());
            assertArrayEquals(o.getVertices(), l.getVertices(), 1e-3f, "body " + i);
        }
        assertEquals("first crate", back.getBody(1).getUserData());
        assertSame(back.getBody(1).getShape(), back.getBody(2).getShape(), "a shared shape stays one shape");
        assertEquals(0, back.getBody(1).getShape().getId(), "the shape set's ids are the file's shape numbers");
        assertSame(back.getBody(1).getShape(), back.getShapeSet().getShape(0));
        assertEquals("crate", back.getBody(1).getShape().getUserData());
        assertEquals(w.getConstraintCount(), back.getConstraintCount());
        Joint weld = (Joint) back.getConstraint(0);
        assertTrue(weld.isFixed());
        assertEquals("weld", weld.getUserData());
        Spring rope = (Spring) back.getConstraint(1);
        assertEquals(((Spring) w.getConstraint(1)).getRestLength(), rope.getRestLength(), fx);
        assertEquals(40f, rope.getCoefficient());
        Motor spin = (Motor) back.getConstraint(2);
        assertEquals(2.5f, spin.getTargetAngularVelocity(), 1e-6f);
        assertEquals(400f, spin.getMaxForce(), 400f * 1e-3f, "the cap is stored as the impulse per tick and read back");
        Motor drive = (Motor) back.getConstraint(3);
        assertEquals(30f, drive.getTargetVelocityX());
        assertTrue(drive.isOrthogonal());
        assertEquals(2, back.getLandscape().getSegmentCount());
        assertEquals(Landscape.FACE_LEFT, back.getLandscape().getFace(0));
        assertEquals(0.4f, back.getLandscape().getFriction(), fx);
    }

    @Test
    void theLoadedWorldMovesAsTheSavedOneDid() throws IOException {
        World w = level();
        World back = saveAndLoad(w, new WorldWriter());
        for (int t = 0; t < 60; t++) {
            w.tick();
            back.tick();
        }
        // Positions were rounded to 1/4096 px: after 3 s the two worlds still agree within 0.05 px.
        for (int i = 0; i < w.getBodyCount(); i++) {
            assertEquals(w.getBody(i).getX(), back.getBody(i).getX(), 0.05f, "body " + i);
            assertEquals(w.getBody(i).getY(), back.getBody(i).getY(), 0.05f, "body " + i);
        }
        assertTrue(Math.abs(w.getBody(3).getAngularVelocity() - 2.5f) < 0.1f, "the motor drove the wheel");
    }

    @Test
    void whatTheFormatCannotHoldIsListedNotDropped() throws IOException {
        World w = level();
        w.setTicksPerSecond(60);
        w.getBody(1).setKinematic(false);
        w.addConstraint(RevoluteJoint.atWorldPoint(w.getBody(3), w.getBody(4), 80, 30));
        w.addEvent(Event.createPositionEvent(null, null, 0, 0, 10, 10));
        Body odd = new Body(0, 0, Shape.createCircle(2.5f), true);
        w.addBody(odd);
        WorldWriter writer = new WorldWriter();
        World back = saveAndLoad(w, writer);
        String notSaved = String.join("\n", writer.getNotSaved());
        assertTrue(notSaved.contains("timestep"), notSaved);
        assertTrue(notSaved.contains("constraint 4 (RevoluteJoint)"), notSaved);
        assertTrue(notSaved.contains("1 events"), notSaved);
        assertTrue(notSaved.contains("radius 2.5 is truncated to 2 px"), notSaved);
        assertEquals(w.getConstraintCount() - 1, back.getConstraintCount());
    }
}
