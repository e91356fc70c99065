package org.emini.constraint;

import java.util.Random;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.world.World;
import org.emini.event.Event;
import org.emini.event.PhysicsEventListener;
import org.emini.shape.Shape;

/**
 * A busy scene with every kind of constraint, an external force and every event type, on top of a
 * pile of bodies: for the allocation and determinism tests.
 */
final class Machine implements PhysicsEventListener {
    final World world = new World();
    int notifications;
    long eventHash = 17;

    Machine(long seed) {
        Random random = new Random(seed);
        world.setPhysicsEventListener(this);
        world.addBody(new Body(0f, 10f, Shape.createRectangle(800f, 20f), false));
        Body pivot = Rigs.anchor(world, 0f, -300f);

        // A chain of loose joints with a welded pair at its end.
        Shape link = Shape.createRectangle(20f, 4f);
        Body previous = pivot;
        for (int i = 0; i < 8; i++) {
            Body b = new Body(20f * i + 10f, -300f, link, true);
            world.addBody(b);
            Joint j = Joint.atWorldPoint(previous, b, 20f * i, -300f, i == 7);
            j.setCollisionLayer(i % 2);
            world.addConstraint(j);
            previous = b;
        }
        // Springs: a rod, a spring by coefficient and one by frequency.
        Shape disc = Shape.createCircle(6f);
        Body a = new Body(-150f, -250f, disc, true);
        Body b = new Body(-100f, -250f, disc, true);
        Body c = new Body(-200f, -200f, disc, true);
        world.addBody(a);
        world.addBody(b);
        world.addBody(c);
        world.addConstraint(new Spring(pivot, a, 0f, 0f, 0f, 0f));
        Spring soft = new Spring(a, b, 0f, 0f, 2f, 0f, 30f);
        soft.setCoefficient(40f);
        soft.setDamping(0.5f);
        world.addConstraint(soft);
        Spring tuned = new Spring(pivot, c, -20f, 0f, 0f, 0f);
        tuned.setFrequency(2f, 0.1f);
        world.addConstraint(tuned);
        // Motors of every mode, and a user-written rail.
        Body cart = new Body(200f, -100f, Shape.createRectangle(30f, 10f), true);
        world.addBody(cart);
        world.addConstraint(new CustomConstraintTest.Rail(cart, -100f));
        Motor drive = new Motor(cart, 20f, 0f, 50f);
        drive.setRelative(true);
        world.addConstraint(drive);
        Body spinner = new Body(-250f, -50f, Shape.createRectangle(20f, 20f), true);
        world.addBody(spinner);
        world.addConstraint(new Motor(spinner, 3f, 5000f));
        Motor brake = new Motor(c, 5f, 5f, 30f);
        brake.setOrthogonal(true);
        world.addConstraint(brake);
        // Rain on the ground, and a wind.
        Shape[] shapes = {Shape.createRectangle(14f, 10f), Shape.createCircle(6f), Shape.createRegularPolygon(8f, 6)};
        for (int i = 0; i < 60; i++) {
            Body r = new Body(random.nextFloat() * 500f - 250f, -50f - random.nextFloat() * 300f, shapes[i % 3], true);
            r.setAngle(random.nextFloat() * 3f);
            world.addBody(r);
        }
        world.addExternalForce((w, dt) -> {
            for (int i = 0; i < w.getBodyCount(); i++) {
                Body body = w.getBody(i);
                if (body.isDynamic() && body.getShape() == shapes[1]) {
                    body.applyForce(3f, 0f);
                }
            }
        });
        // Every event type, filtered and unfiltered, some trigger-once.
        Body sensor = new Body(0f, -20f, Shape.createRectangle(200f, 40f), false);
        Event[] events = {
            Event.createPositionEvent(null, null, -100f, -200f, 100f, 0f),
            Event.createVelocityEvent(null, shapes[0], 10f, 1000f),
            Event.createAngleEvent(spinner, null, 0f, 1f),
            Event.createAngularVelocityEvent(null, null, 1f, 10f),
            Event.createCollisionEvent(null, null, true, true, true, true),
            Event.createCollisionEvent(cart, null, false, true, false, true),
            Event.createRelativeCollisionEvent(null, shapes[2], 0.5f, 2.5f),
            Event.createSensorEvent(null, null, sensor),
            Event.createConstraintForceEvent(null, 50f, Float.POSITIVE_INFINITY),
            Event.createConstraintForceEvent(soft, 0f, 20f),
        };
        for (int i = 0; i < events.length; i++) {
            events[i].setTriggerOnce(i % 3 == 0);
            world.addEvent(events[i]);
        }
    }

    @Override
    public void eventTriggered(Event event, Object parameter) {
        notifications++;
        long id = parameter instanceof Body ? ((Body) parameter).getId() : parameter instanceof Constraint ? 1000 : 2000;
        eventHash = 31 * eventHash + 7 * event.getType() + id;
    }

    void run(int ticks) {
        for (int i = 0; i < ticks; i++) {
            world.tick();
        }
    }

    long hash() {
        long h = eventHash;
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            h = 31 * h + Float.floatToIntBits(b.getX());
            h = 31 * h + Float.floatToIntBits(b.getY());
            h = 31 * h + Float.floatToIntBits(b.getAngle());
            h = 31 * h + Float.floatToIntBits(b.getVelocityX());
            h = 31 * h + Float.floatToIntBits(b.getAngularVelocity());
        }
        for (int i = 0; i < world.getConstraintCount(); i++) {
            h = 31 * h + Float.floatToIntBits(world.getConstraint(i).getForce());
        }
        return h;
    }
}
