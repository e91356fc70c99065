package org.emini.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.constraint.Joint;
import org.emini.constraint.Motor;
import org.emini.constraint.RevoluteJoint;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.SolverStep;
import org.emini.event.Event;
import org.emini.shape.Circle;
import org.emini.shape.Shape;
import org.emini.shape.ShapeSet;
import org.junit.jupiter.api.Test;

/** The original's API that ported code expects (issue 21, item 2): each call does what the original's did. */
class PortingApiTest {
    /** A scene with every kind of thing World(World) copies: bodies, a landscape, the manual's three constraints, a force, an event. */
    private static World scene() {
        World w = new World();
        w.setDampingLateral(0.01f);
        w.getLandscape().addSegment(-300, 100, 300, 100);
        Body ground = new Body(0, 80, Shape.createRectangle(200, 20), false);
        w.addBody(ground);
        Shape box = Shape.createRectangle(20, 20);
        box.setFriction(0.5f);
        Body a = new Body(-40, 0, box, true);
        Body b = new Body(-10, 0, box, true);
        Body wheel = new Body(60, 20, Shape.createCircle(10), true);
        w.addBody(a);
        w.addBody(b);
        w.addBody(wheel);
        w.addConstraint(new Joint(a, b, 15, 0, -15, 0, true));
        Spring spring = new Spring(ground, a, 0, -100, 0, 0, Spring.MEASURE_DISTANCE);
        spring.setCoefficient(20);
        w.addConstraint(spring);
        w.addConstraint(new Motor(wheel, 3f, 5000f));
        w.addExternalForce((world, dt) -> world.getBody(1).applyForce(30f, 0f));
        w.addEvent(Event.createCollisionEvent(wheel, null, false, false, true, false));
        return w;
    }

    @Test
    void aCopiedWorldTicksBitForBitLikeTheOriginal() {
        World original = scene();
        original.getLandscape().setFriction(0.75f);
        World copy = new World(original);
        assertEquals(0.75f, copy.getLandscape().getFriction());
        assertEquals(original.getBodyCount(), copy.getBodyCount());
        assertEquals(original.getConstraintCount(), copy.getConstraintCount());
        assertEquals(1, copy.getExternalForceCount());
        assertEquals(1, copy.getEventCount());
        assertEquals(1, copy.getLandscape().getSegmentCount());
        assertEquals(0.01f, copy.getDampingLateral());
        for (int t = 0; t < 200; t++) {
            original.tick();
            copy.tick();
        }
        for (int i = 0; i < original.getBodyCount(); i++) {
            Body o = original.getBody(i);
            Body c = copy.getBody(i);
            assertNotSame(o, c);
            assertSame(o.getShape(), c.getShape(), "shapes are shared, as in the original");
            assertEquals(o.getX(), c.getX(), 0f, "body " + i);
            assertEquals(o.getY(), c.getY(), 0f, "body " + i);
            assertEquals(o.getAngle(), c.getAngle(), 0f, "body " + i);
        }
        // The spring, the motor and the force acted: the copy is not a world at rest.
        assertTrue(Math.abs(copy.getBody(3).getAngularVelocity() - 3f) < 0.5f, "motor " + copy.getBody(3).getAngularVelocity());
    }

    @Test
    void addWorldCopiesEverythingInAndReturnsTheBodyMapping() {
        World level = scene();
        World game = new World();
        Body player = new Body(500, 0, Shape.createCircle(5), true);
        game.addBody(player);
        Body[] map = game.addWorld(level);
        assertEquals(level.getBodyCount(), map.length);
        assertEquals(1 + level.getBodyCount(), game.getBodyCount());
        for (int i = 0; i < map.length; i++) {
            assertSame(game, map[i].getWorld());
            assertEquals(level.getBody(i).getX(), map[i].getX());
        }
        Joint joint = (Joint) game.getConstraint(0);
        assertSame(map[1], joint.getBodyA());
        assertSame(map[2], joint.getBodyB());
        assertSame(map[3], ((Motor) game.getConstraint(2)).getBody());
        assertSame(map[3], game.getEvent(0).getBody());
        assertEquals(level.getBodyCount(), level.getBodies().length, "the source is unchanged");
        assertThrows(IllegalArgumentException.class, () -> game.addWorld(game));
    }

    @Test
    void aConstraintThatCannotBeCopiedIsRefusedByNameAndNothingIsAdded() {
        World w = new World();
        Body a = new Body(0, 0, Shape.createCircle(5), true);
        Body b = new Body(20, 0, Shape.createCircle(5), true);
        w.addBody(a);
        w.addBody(b);
        w.addConstraint(new Spring(a, b, 0, 0, 0, 0));
        w.addConstraint(RevoluteJoint.atWorldPoint(a, b, 10, 0));
        World target = new World();
        UnsupportedOperationException e = assertThrows(UnsupportedOperationException.class, () -> target.addWorld(w));
        assertTrue(e.getMessage().contains("RevoluteJoint.copy"), e.getMessage());
        assertEquals(0, target.getBodyCount());
        assertEquals(0, target.getConstraintCount());
    }

    @Test
    void arraysOfBodiesAndConstraintsFollowTheWorldsOrder() {
        World w = scene();
        Body[] bodies = w.getBodies();
        Constraint[] constraints = w.getConstraints();
        assertEquals(w.getBodyCount(), bodies.length);
        assertEquals(w.getConstraintCount(), constraints.length);
        for (int i = 0; i < bodies.length; i++) {
            assertSame(w.getBody(i), bodies[i]);
        }
        for (int i = 0; i < constraints.length; i++) {
            assertSame(w.getConstraint(i), constraints[i]);
        }
        assertSame(bodies[3], w.findBodyAt(60, 20), "the body-at-point lookup (the original's findBodyAt)");
    }

    @Test
    void verticesAreTheShapesOutlineInWorldCoordinates() {
        Body box = new Body(100, 50, Shape.createRectangle(40, 20), true);
        box.setAngleDegrees(90);
        float[] v = box.getVertices();
        assertEquals(8, v.length);
        // Turned by 90°, the 40 × 20 box spans 20 px in x and 40 in y around its position.
        float minX = Float.MAX_VALUE, maxX = -Float.MAX_VALUE, minY = Float.MAX_VALUE, maxY = -Float.MAX_VALUE;
        for (int i = 0; i < 4; i++) {
            minX = Math.min(minX, v[2 * i]);
            maxX = Math.max(maxX, v[2 * i]);
            minY = Math.min(minY, v[2 * i + 1]);
            maxY = Math.max(maxY, v[2 * i + 1]);
        }
        assertEquals(90f, minX, 1e-4f);
        assertEquals(110f, maxX, 1e-4f);
        assertEquals(30f, minY, 1e-4f);
        assertEquals(70f, maxY, 1e-4f);
        // A circle: one point on its rim at the body's angle; its distance from the centre is the radius.
        Body ball = new Body(10, 20, Shape.createCircle(7), true);
        ball.setAngleDegrees(90);
        assertArrayEquals(new float[] {10f, 27f}, ball.getVertices(), 1e-5f);
    }

    @Test
    void shapeSetsNumberShapesAndCopiesKeepMaterialIdAndUserData() {
        ShapeSet set = new ShapeSet();
        Shape a = Shape.createRectangle(10, 10);
        Shape b = Shape.createCircle(4);
        assertEquals(-1, a.getId());
        assertEquals(0, set.register(a));
        assertEquals(1, set.register(b));
        assertEquals(0, set.register(a), "a registered shape keeps its place");
        assertEquals(1, b.getId());
        assertSame(b, set.getShape(1));
        b.setElasticityPercent(80);
        b.setMass(3);
        b.setUserData("ball image");
        Shape copy = b.copy();
        assertNotSame(b, copy);
        assertEquals(4f, ((Circle) copy).getRadius());
        assertEquals(b.getElasticity(), copy.getElasticity());
        assertEquals(3f, copy.getMass());
        assertEquals(b.getInertia(), copy.getInertia());
        assertEquals(1, copy.getId());
        assertEquals("ball image", copy.getUserData());
        Body body = new Body(1, 2, b, true);
        body.setUserData("player");
        Body bodyCopy = body.copy();
        assertSame(b, bodyCopy.getShape());
        assertEquals("player", bodyCopy.getUserData());
        World w = new World();
        w.setUserData("level 1");
        assertEquals("level 1", new World(w).getUserData(), "world user data is shared by a copy");
    }

    @Test
    void constraintsCarryUserDataAndTheirCopiesKeepSettings() {
        World w = scene();
        Spring spring = (Spring) w.getConstraint(1);
        spring.setUserData("rope");
        spring.setDamping(2f);
        Joint joint = (Joint) w.getConstraint(0);
        joint.setUserData("weld");
        World copy = new World(w);
        Spring springCopy = (Spring) copy.getConstraint(1);
        assertEquals("rope", springCopy.getUserData());
        assertEquals(spring.getRestLength(), springCopy.getRestLength());
        assertEquals(20f, springCopy.getCoefficient());
        assertEquals(2f, springCopy.getDamping());
        assertEquals("weld", copy.getConstraint(0).getUserData());
        assertEquals(joint.getReferenceAngle(), ((Joint) copy.getConstraint(0)).getReferenceAngle());
        Motor motor = (Motor) copy.getConstraint(2);
        assertEquals(3f, motor.getTargetAngularVelocity());
        assertEquals(5000f, motor.getMaxForce());
    }

    @Test
    void aNegativeRestLengthMeasuresTheDistanceAsTheOriginalsMinusOne() {
        World w = new World();
        Body a = new Body(0, 0, Shape.createCircle(5), false);
        Body b = new Body(30, 40, Shape.createCircle(5), true);
        w.addBody(a);
        w.addBody(b);
        assertEquals(50f, new Spring(a, b, 0, 0, 0, 0, -1f).getRestLength(), 1e-4f);
        assertEquals((float) Math.hypot(30, 30), new Spring(a, b, 0, 0, 0, -10, Spring.MEASURE_DISTANCE).getRestLength(), 1e-4f);
        assertEquals(12f, new Spring(a, b, 0, 0, 0, 0, 12f).getRestLength());
    }

    @Test
    void integerGravityPointsStraightDownTheScreen() {
        World w = new World();
        w.setGravity(0f, 0f);
        w.setGravity(250);
        assertEquals(0f, w.getGravityX());
        assertEquals(250f, w.getGravityY());
    }

    @Test
    void totalEnergyIsConservedByAFreeFallAndAnUndampedSpring() {
        World fall = new World();
        Body stone = new Body(0, 0, Shape.createCircle(5), true);
        stone.setVelocity(40, -100);
        fall.addBody(stone);
        float start = fall.getTotalEnergy();
        assertEquals(0.5f * (40 * 40 + 100 * 100), start, 1e-2f, "kinetic energy, potential 0 at the origin");
        for (int t = 0; t < 40; t++) {
            fall.tick();
        }
        // The substeps' first-order error: Emini's position leads by g·(h/N)·t/2, 0.5 px after 2 s.
        assertEquals(start, fall.getTotalEnergy(), 0.01f * start);

        World bob = new World();
        bob.setGravity(0);
        Body anchor = new Body(0, 0, Shape.createRectangle(4, 4), false);
        Body mass = new Body(0, 60, Shape.createCircle(5), true);
        bob.addBody(anchor);
        bob.addBody(mass);
        Spring spring = new Spring(anchor, mass, 0, 0, 0, 0, 50f);
        spring.setCoefficient(10f);
        bob.addConstraint(spring);
        float e0 = bob.getTotalEnergy();
        assertEquals(0.5f * 10f * 10f * 10f, e0, 1e-3f, "½·k·(d − d₀)² with d − d₀ = 10 px");
        float lowest = e0;
        float highest = e0;
        for (int t = 0; t < 400; t++) {
            bob.tick();
            lowest = Math.min(lowest, bob.getTotalEnergy());
            highest = Math.max(highest, bob.getTotalEnergy());
        }
        assertTrue(highest < 1.05f * e0 && lowest > 0.95f * e0, "energy between " + lowest + " and " + highest + " of " + e0);
        assertEquals(0f, bob.getBodyTotalEnergy(anchor), "a static body has none");
    }

    /** The manual's sprite control: a Motor subclass that jumps in prepare (its precalculate). */
    private static final class Jumper extends Motor {
        private float jump;

        Jumper(Body body) {
            super(body, 0f, 0f, 0f);
        }

        @Override
        public void prepare(SolverStep step) {
            if (jump != 0f) {
                getBody().applyAcceleration(0f, jump, 1f);
                jump = 0f;
            }
            super.prepare(step);
        }
    }

    @Test
    void aMotorSubclassActsInTheTickItsPrepareRuns() {
        World w = new World();
        w.setGravity(0);
        Body sprite = new Body(0, 0, Shape.createRectangle(20, 30), true);
        w.addBody(sprite);
        Jumper control = new Jumper(sprite);
        w.addConstraint(control);
        control.jump = -120f;
        w.tick();
        assertEquals(-120f, sprite.getVelocityY(), 1e-3f);
        assertEquals(-120f * w.getTimestep(), sprite.getY(), 1e-3f, "moved in that very tick");
    }

    /** The manual's GraphicsWorld: a World subclass that wraps a loaded world and adds drawing. */
    private static final class CountingWorld extends World {
        CountingWorld(World w) {
            super(w);
        }

        int outlinePoints() {
            int n = 0;
            for (Body b : getBodies()) {
                n += b.getVertices().length / 2;
            }
            return n;
        }
    }

    @Test
    void aWorldSubclassWrapsACopyOfAnotherWorld() {
        CountingWorld w = new CountingWorld(scene());
        assertEquals(4 + 4 + 4 + 1, w.outlinePoints());
        w.tick();
        assertEquals(1, w.getTickCount());
    }
}
