package org.emini.event;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Predicate;
import org.emini.constraint.Motor;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Contact;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * Each event type fires in exactly the ticks where its condition holds, as the test computes it
 * from the public state after the tick, and only once per body with trigger-once.
 */
class EventTest {
    /** Records what the listener was told, with the tick count at the time. */
    static final class Recorder implements PhysicsEventListener {
        final World world;
        final List<long[]> ticks = new ArrayList<>();
        final List<Object> parameters = new ArrayList<>();
        final List<Event> events = new ArrayList<>();

        Recorder(World world) {
            this.world = world;
            world.setPhysicsEventListener(this);
        }

        @Override
        public void eventTriggered(Event event, Object parameter) {
            ticks.add(new long[] {world.getTickCount()});
            parameters.add(parameter);
            events.add(event);
        }

        /** The ticks in which an event fired with a parameter. */
        Set<Long> ticksOf(Event event, Object parameter) {
            Set<Long> s = new HashSet<>();
            for (int i = 0; i < events.size(); i++) {
                if (events.get(i) == event && (parameter == null || parameters.get(i) == parameter)) {
                    s.add(ticks.get(i)[0]);
                }
            }
            return s;
        }

        int count(Event event) {
            int n = 0;
            for (Event e : events) {
                n += e == event ? 1 : 0;
            }
            return n;
        }
    }

    /** Runs and returns the ticks in which the condition held after the tick. */
    private static Set<Long> run(World world, int ticks, Predicate<World> condition) {
        Set<Long> held = new HashSet<>();
        for (int i = 0; i < ticks; i++) {
            world.tick();
            if (condition.test(world)) {
                held.add(world.getTickCount());
            }
        }
        return held;
    }

    private static void assertSameTicks(Set<Long> expected, Set<Long> fired, int ticks) {
        assertFalse(expected.isEmpty(), "the condition never held: the test tests nothing");
        assertTrue(expected.size() < ticks, "the condition always held: the test tests nothing");
        assertEquals(expected, fired);
    }

    private static Body ball(World world, float x, float y) {
        Body b = new Body(x, y, Shape.createCircle(10f), true);
        world.addBody(b);
        return b;
    }

    private static Body ground(World world) {
        Body g = new Body(0f, 10f, Shape.createRectangle(1000f, 20f), false);
        world.addBody(g);
        return g;
    }

    @Test
    void positionEventFiresWhileTheBodyIsInsideTheRectangle() {
        World world = new World();
        Body ball = ball(world, 0f, -300f);
        Event event = Event.createPositionEvent(ball, null, -50f, -200f, 50f, -100f);
        world.addEvent(event);
        Recorder r = new Recorder(world);
        Set<Long> held = run(world, 60, w -> ball.getY() >= -200f && ball.getY() <= -100f);
        assertSameTicks(held, r.ticksOf(event, ball), 60);
        assertSame(ball, r.parameters.get(0));
    }

    @Test
    void velocityEventFiresWhileTheSpeedIsInRange() {
        World world = new World();
        Body ball = ball(world, 0f, 0f);
        ball.setVelocity(30f, -100f);
        Event event = Event.createVelocityEvent(null, null, 40f, 80f);
        world.addEvent(event);
        Recorder r = new Recorder(world);
        Set<Long> held = run(world, 60, w -> {
            double v = Math.hypot(ball.getVelocityX(), ball.getVelocityY());
            return v >= 40.0 && v <= 80.0;
        });
        assertSameTicks(held, r.ticksOf(event, ball), 60);
    }

    @Test
    void angleEventComparesTheAngleWrappedToOneTurn() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body wheel = new Body(0f, 0f, Shape.createRectangle(20f, 20f), true);
        world.addBody(wheel);
        wheel.setAngularVelocity(-2f);
        Event event = Event.createAngleEvent(wheel, null, 4f, 5f);
        world.addEvent(event);
        Recorder r = new Recorder(world);
        Set<Long> held = run(world, 120, w -> {
            double a = wheel.getAngle() % (2 * Math.PI);
            a = a < 0 ? a + 2 * Math.PI : a;
            return a >= 4.0 && a <= 5.0;
        });
        // Turning backwards through three turns: the wrapped angle passes 4..5 each turn.
        assertSameTicks(held, r.ticksOf(event, wheel), 120);
        assertTrue(wheel.getAngle() < -10f);
    }

    @Test
    void angularVelocityEventFiresWhileAMotorSpinsTheBodyThroughTheRange() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body wheel = new Body(0f, 0f, Shape.createCircle(10f), true);
        world.addBody(wheel);
        world.addConstraint(new Motor(wheel, 6f, 2f * wheel.getInertia()));
        Event event = Event.createAngularVelocityEvent(wheel, null, 1f, 2.5f);
        world.addEvent(event);
        Recorder r = new Recorder(world);
        Set<Long> held = run(world, 80, w -> wheel.getAngularVelocity() >= 1f && wheel.getAngularVelocity() <= 2.5f);
        assertSameTicks(held, r.ticksOf(event, wheel), 80);
    }

    /** Whether a body has a contact point that touches, in the sides the flags enable. */
    private static boolean touching(World world, Body body, boolean above, boolean below) {
        for (int i = 0; i < world.getContactCount(); i++) {
            Contact c = world.getContact(i);
            if (c.getBodyA() != body && c.getBodyB() != body) {
                continue;
            }
            for (int p = 0; p < c.getPointCount(); p++) {
                boolean touches = c.getSeparation(p) <= 0f || c.getNormalImpulse(p) > 0f || c.getMaxNormalImpulse(p) > 0f;
                float dy = c.getPointY(p) - body.getY();
                if (touches && ((above && dy < 0f) || (below && dy > 0f))) {
                    return true;
                }
            }
        }
        return false;
    }

    @Test
    void collisionEventFiresFromTheTickTheBallLandsAndReportsTheContact() {
        World world = new World();
        ground(world);
        Body ball = ball(world, 0f, -100f);
        Event below = Event.createCollisionEvent(ball, null, false, false, true, false);
        Event above = Event.createCollisionEvent(ball, null, true, false, false, false);
        world.addEvent(below);
        world.addEvent(above);
        Recorder r = new Recorder(world);
        long[] landed = {-1};
        Set<Long> held = run(world, 60, w -> {
            if (landed[0] < 0 && ball.getVelocityY() < 1f && ball.getY() > -20f) {
                landed[0] = w.getTickCount();
            }
            return touching(w, ball, false, true);
        });
        assertSameTicks(held, r.ticksOf(below, null), 60);
        assertEquals(0, r.count(above));
        // It fires in the tick in which the ball is stopped, and the parameter is the contact.
        assertEquals(landed[0], (long) r.ticksOf(below, null).stream().min(Long::compare).get());
        Contact c = (Contact) r.parameters.get(0);
        assertSame(ball, c.getOther(c.getOther(ball)));
    }

    @Test
    void collisionEventForEveryBodyReportsEachTouchingContactOnce() {
        World world = new World();
        ground(world);
        Body low = ball(world, -100f, -20f);
        Body high = ball(world, 100f, -200f);
        Event any = Event.createCollisionEvent(null, null, true, true, true, true);
        world.addEvent(any);
        Recorder r = new Recorder(world);
        Set<Long> lowHeld = new HashSet<>();
        Set<Long> highHeld = new HashSet<>();
        for (int t = 0; t < 60; t++) {
            world.tick();
            if (touching(world, low, true, true)) {
                lowHeld.add(world.getTickCount());
            }
            if (touching(world, high, true, true)) {
                highHeld.add(world.getTickCount());
            }
        }
        Set<Long> lowFired = new HashSet<>();
        Set<Long> highFired = new HashSet<>();
        for (int i = 0; i < r.events.size(); i++) {
            Contact c = (Contact) r.parameters.get(i);
            (c.getBodyA() == low || c.getBodyB() == low ? lowFired : highFired).add(r.ticks.get(i)[0]);
        }
        assertEquals(lowHeld, lowFired);
        assertEquals(highHeld, highFired);
        assertTrue(lowFired.size() > highFired.size() && !highFired.isEmpty());
        // One report per contact and tick.
        assertEquals(lowFired.size() + highFired.size(), r.events.size());
    }

    @Test
    void relativeCollisionEventMeasuresDirectionsInTheBodysFrame() {
        World world = new World();
        ground(world);
        Body upright = new Body(-100f, -10f, Shape.createRectangle(30f, 20f), true);
        Body flipped = new Body(100f, -10f, Shape.createRectangle(30f, 20f), true);
        flipped.setAngle((float) Math.PI);
        world.addBody(upright);
        world.addBody(flipped);
        // "Standing on something": contact points below the body in its own frame. The points are
        // the bottom corners, at atan2(10, ±15) = 34° and 146° from the body's x axis.
        Event standing = Event.createRelativeCollisionEvent(null, null, (float) (Math.PI / 8), (float) (7 * Math.PI / 8));
        Event headFirst = Event.createRelativeCollisionEvent(null, null, (float) (-7 * Math.PI / 8), (float) (-Math.PI / 8));
        world.addEvent(standing);
        world.addEvent(headFirst);
        Recorder r = new Recorder(world);
        Set<Long> touched = run(world, 20, w -> touching(w, upright, false, true));
        assertEquals(touched, r.ticksOf(standing, null));
        assertEquals(touched.size(), r.count(standing));
        assertEquals(r.ticksOf(standing, null), r.ticksOf(headFirst, null));
        for (int i = 0; i < r.events.size(); i++) {
            Contact c = (Contact) r.parameters.get(i);
            Body reported = c.getBodyA() == upright || c.getBodyB() == upright ? upright : flipped;
            assertSame(r.events.get(i) == standing ? upright : flipped, reported);
        }
    }

    @Test
    void sensorEventFiresWhileTheBallOverlapsTheSensor() {
        World world = new World();
        Body ball = ball(world, 0f, -300f);
        Body other = new Body(300f, -300f, Shape.createCircle(10f), true);
        world.addBody(other);
        // A 100×40 sensor that is not in the world.
        Body sensor = new Body(0f, -100f, Shape.createRectangle(100f, 40f), false);
        Event event = Event.createSensorEvent(null, null, sensor);
        world.addEvent(event);
        Recorder r = new Recorder(world);
        Set<Long> held = run(world, 60, w -> {
            // Circle against the axis-aligned box: the nearest point of the box within the radius.
            double dy = Math.max(0.0, Math.abs(ball.getY() + 100.0) - 20.0);
            double dx = Math.max(0.0, Math.abs(ball.getX()) - 50.0);
            return Math.hypot(dx, dy) <= 10.0;
        });
        assertSameTicks(held, r.ticksOf(event, ball), 60);
        assertTrue(r.ticksOf(event, other).isEmpty());
    }

    @Test
    void constraintForceEventFiresAtTheBottomOfTheSwingWhereTheRodCarriesThreeTimesTheWeight() {
        // A point mass on a rigid rod released horizontally: tension m·g + m·v²/L = 3·m·g at the bottom.
        World world = new World();
        world.setTicksPerSecond(60f);
        Body pivot = new Body(0f, 0f, Shape.createRectangle(4f, 4f), false);
        world.addBody(pivot);
        Body bob = ball(world, 100f, 0f);
        bob.setRotatable(false);
        Spring rod = new Spring(pivot, bob, 0f, 0f, 0f, 0f);
        world.addConstraint(rod);
        float weight = bob.getMass() * world.getGravityY();
        Event event = Event.createConstraintForceEvent(rod, 2.9f * weight, Float.POSITIVE_INFINITY);
        world.addEvent(event);
        Recorder r = new Recorder(world);
        float[] largest = {0f};
        Set<Long> held = run(world, 200, w -> {
            largest[0] = Math.max(largest[0], rod.getForce());
            return rod.getForce() >= 2.9f * weight;
        });
        assertSameTicks(held, r.ticksOf(event, rod), 200);
        assertEquals(3f * weight, largest[0], 0.01f * 3f * weight);
        for (long t : r.ticksOf(event, rod)) {
            assertTrue(t > 0);
        }
    }

    @Test
    void triggerOnceReportsEachBodyOnlyTheFirstTime() {
        World world = new World();
        Shape small = Shape.createCircle(5f);
        Body a = new Body(0f, -300f, small, true);
        Body b = new Body(50f, -350f, small, true);
        Body c = ball(world, 100f, -300f);
        world.addBody(a);
        world.addBody(b);
        // Every body with the small shape, once each, while between y = −250 and −150.
        Event once = Event.createPositionEvent(null, small, -1000f, -250f, 1000f, -150f);
        once.setTriggerOnce(true);
        Event every = Event.createPositionEvent(null, small, -1000f, -250f, 1000f, -150f);
        world.addEvent(once);
        world.addEvent(every);
        Recorder r = new Recorder(world);
        Rigs.runTicks(world, 60);
        assertEquals(1, r.ticksOf(once, a).size());
        assertEquals(1, r.ticksOf(once, b).size());
        assertTrue(r.ticksOf(once, c).isEmpty() && r.ticksOf(every, c).isEmpty());
        assertEquals(2, r.count(once));
        // The one report is the first tick of the many in which it held.
        assertTrue(r.ticksOf(every, a).size() > 3);
        assertEquals(r.ticksOf(every, a).stream().min(Long::compare).get(), r.ticksOf(once, a).iterator().next());
        // After reset it may report again.
        once.reset();
        a.setPosition(0f, -200f);
        a.setVelocity(0f, 0f);
        world.tick();
        assertEquals(3, r.count(once));
    }

    @Test
    void withoutAListenerNothingIsChecked() {
        World world = new World();
        Body ball = ball(world, 0f, 0f);
        Event once = Event.createPositionEvent(ball, null, -10f, -10f, 10f, 10f);
        once.setTriggerOnce(true);
        world.addEvent(once);
        world.tick();
        // Had it been checked, trigger-once would have used up the body.
        Recorder r = new Recorder(world);
        world.tick();
        assertEquals(1, r.count(once));
        world.setPhysicsEventListener(null);
        world.tick();
        assertEquals(1, r.count(once));
        assertTrue(world.removeEvent(once));
        assertFalse(world.removeEvent(once));
    }

    @Test
    void eventsRefuseMeaninglessRanges() {
        assertThrows(IllegalArgumentException.class, () -> Event.createPositionEvent(null, null, 10f, 0f, 0f, 5f));
        assertThrows(IllegalArgumentException.class, () -> Event.createVelocityEvent(null, null, -1f, 5f));
        assertThrows(IllegalArgumentException.class, () -> Event.createAngleEvent(null, null, Float.NaN, 1f));
        assertThrows(IllegalArgumentException.class, () -> Event.createConstraintForceEvent(null, 5f, 1f));
        assertThrows(IllegalArgumentException.class, () -> Event.createRelativeCollisionEvent(null, null, 0f, 7f));
        assertThrows(IllegalArgumentException.class, () -> Event.createSensorEvent(null, null, null));
        World world = new World();
        Event e = Event.createAngleEvent(null, null, 0f, 1f);
        world.addEvent(e);
        assertThrows(IllegalArgumentException.class, () -> world.addEvent(e));
    }
}
