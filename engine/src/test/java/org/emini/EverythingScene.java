package org.emini;

import java.util.Random;
import org.emini.constraint.Joint;
import org.emini.constraint.Motor;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Landscape;
import org.emini.world.World;
import org.emini.event.Event;
import org.emini.event.PhysicsEventListener;
import org.emini.particle.ParticleEmitter;
import org.emini.shape.Shape;

/**
 * One fixed scene that uses every feature of the engine at once (each shape kind, multi-shapes,
 * static, dynamic and bullet bodies, layers, materials, tilted gravity, damping, landscape with faces,
 * loose and fixed joints, rigid and soft springs, motors of each mode, an external force, events of
 * each kind, a particle emitter and a simulation area), and a hash of its whole state: the pinned
 * determinism hash that every change of results must update on purpose.
 */
public final class EverythingScene implements PhysicsEventListener {
    /** The world, built by the constructor. */
    public final World world = new World();
    private final ParticleEmitter emitter;
    private long eventHash = 17;
    private int eventCount;

    /**
     * Builds the scene.
     *
     * @param dynamicIterations whether the world uses dynamic iteration counts
     */
    public EverythingScene(boolean dynamicIterations) {
        Random random = new Random(20261124L);
        world.setGravity(8f, 100f);
        world.setDampingLateral(0.002f);
        world.setDampingRotational(0.01f);
        world.setConstraintIterationDynamic(dynamicIterations);
        world.setPhysicsEventListener(this);

        // Static ground and walls, one of them tilted, and a landscape floor with faces.
        Shape ground = Shape.createRectangle(900f, 20f);
        ground.setFriction(0.8f);
        world.addBody(new Body(0f, 10f, ground, false));
        Body wall = new Body(-420f, -200f, Shape.createRectangle(20f, 400f), false);
        wall.setAngle(0.1f);
        world.addBody(wall);
        world.addBody(new Body(420f, -200f, Shape.createRectangle(20f, 400f), false));
        Landscape land = new Landscape();
        land.addSegment(-400f, -40f, -200f, -10f, 1);
        land.addSegment(-200f, -10f, 0f, -30f, 2);
        land.addSegment(0f, -30f, 200f, 0f);
        land.setFriction(0.6f);
        land.setElasticity(0.2f);
        world.setLandscape(land);

        // Rain of every shape kind, some elastic, some on their own layer.
        Shape box = Shape.createRectangle(14f, 10f);
        Shape ball = Shape.createCircle(6f);
        ball.setElasticity(0.7f);
        Shape hexagon = Shape.createRegularPolygon(8f, 6);
        Shape wedge = Shape.createPolygon(0f, 0f, 16f, 4f, 4f, 12f);
        Shape heavy = Shape.createRectangle(10f, 10f);
        heavy.setMass(20f);
        Shape dumbbell = Shape.createMultiShape(Shape.createCircle(5f), Shape.createRectangle(20f, 4f));
        Shape[] shapes = {box, ball, hexagon, wedge, heavy, dumbbell};
        for (int i = 0; i < 72; i++) {
            Body b = new Body(random.nextFloat() * 700f - 350f, -80f - random.nextFloat() * 500f, shapes[i % shapes.length], true);
            b.setAngle(random.nextFloat() * 3f);
            if (i % 9 == 4) {
                b.setCollisionLayers(2);
            }
            if (i % 11 == 3) {
                b.setRotatable(false);
            }
            world.addBody(b);
        }
        Body bullet = new Body(-380f, -120f, Shape.createCircle(2f), true);
        bullet.setBullet(true);
        bullet.setVelocity(2500f, -200f);
        bullet.setGravityAffected(false);
        world.addBody(bullet);

        // A chain of loose joints from a static pivot, ending in a welded pair.
        Body pivot = new Body(150f, -400f, Shape.createCircle(3f), false);
        world.addBody(pivot);
        Shape link = Shape.createRectangle(20f, 4f);
        Body previous = pivot;
        for (int i = 0; i < 6; i++) {
            Body b = new Body(150f + 20f * i + 10f, -400f, link, true);
            world.addBody(b);
            world.addConstraint(Joint.atWorldPoint(previous, b, 150f + 20f * i, -400f, i == 5));
            previous = b;
        }
        // Springs: a rigid rod, one by coefficient and one by frequency.
        Body a = new Body(-150f, -350f, ball, true);
        Body c = new Body(-100f, -350f, box, true);
        Body d = new Body(-200f, -300f, hexagon, true);
        world.addBody(a);
        world.addBody(c);
        world.addBody(d);
        world.addConstraint(new Spring(pivot, a, 0f, 0f, 0f, 0f));
        Spring soft = new Spring(a, c, 0f, 0f, 2f, 0f, 30f);
        soft.setCoefficient(40f);
        soft.setDamping(0.5f);
        world.addConstraint(soft);
        Spring tuned = new Spring(pivot, d, -20f, 0f, 0f, 0f);
        tuned.setFrequency(2f, 0.1f);
        world.addConstraint(tuned);
        // Motors of every mode.
        Body cart = new Body(250f, -60f, Shape.createRectangle(30f, 10f), true);
        world.addBody(cart);
        Motor drive = new Motor(cart, 20f, 0f, 50f);
        drive.setRelative(true);
        world.addConstraint(drive);
        Body spinner = new Body(-250f, -80f, Shape.createRectangle(20f, 20f), true);
        world.addBody(spinner);
        world.addConstraint(new Motor(spinner, 3f, 5000f));
        Motor brake = new Motor(d, 5f, 5f, 30f);
        brake.setOrthogonal(true);
        world.addConstraint(brake);
        // A wind on the balls.
        world.addExternalForce((w, dt) -> {
            for (int i = 0; i < w.getBodyCount(); i++) {
                Body body = w.getBody(i);
                if (body.isDynamic() && body.getShape() == ball) {
                    body.applyForce(3f, 0f);
                }
            }
        });
        // Events of each kind.
        Body sensor = new Body(0f, -60f, Shape.createRectangle(120f, 40f), false);
        sensor.setInteracting(false);
        world.addBody(sensor);
        world.addEvent(Event.createPositionEvent(null, null, -100f, -100f, 100f, 0f));
        world.addEvent(Event.createVelocityEvent(null, ball, 50f, 1e9f));
        world.addEvent(Event.createAngleEvent(spinner, null, 1f, 2f));
        world.addEvent(Event.createAngularVelocityEvent(null, null, 2f, 100f));
        world.addEvent(Event.createCollisionEvent(null, box, true, true, true, true));
        world.addEvent(Event.createRelativeCollisionEvent(cart, null, 0f, 3.14f));
        world.addEvent(Event.createSensorEvent(null, null, sensor));
        world.addEvent(Event.createConstraintForceEvent(tuned, 10f, 1e9f));
        // Sparks from the cart, bouncing off bodies and the landscape.
        emitter = new ParticleEmitter(200, cart);
        emitter.setCreationRate(120f, 20f);
        emitter.setLifetime(1.5f, 0.5f);
        emitter.setSpeed(80f, 20f);
        emitter.setAngle(-1.57f, 0.8f);
        emitter.setCanCollide(true);
        emitter.setElasticity(0.5f);
        emitter.setSeed(99L);
        world.addParticleEmitter(emitter);
        // A simulation area that leaves out the top of the rain until it falls in.
        world.setSimulationArea(-500f, -450f, 500f, 100f);
    }

    @Override
    public void eventTriggered(Event event, Object parameter) {
        eventCount++;
        eventHash = 31 * eventHash + event.getType();
        if (parameter instanceof Body) {
            eventHash = 31 * eventHash + ((Body) parameter).getId();
        }
    }

    /**
     * Runs ticks.
     *
     * @param ticks how many
     */
    public void run(int ticks) {
        for (int i = 0; i < ticks; i++) {
            world.tick();
        }
    }

    /**
     * The number of event notifications so far.
     *
     * @return the count
     */
    public int getEventCount() {
        return eventCount;
    }

    /**
     * A hash of every body's pose and velocity, every constraint's force, the contacts, the particles
     * and the events seen so far.
     *
     * @return the hash
     */
    public long hash() {
        long h = bodyHash(world);
        for (int i = 0; i < world.getConstraintCount(); i++) {
            h = mix(h, world.getConstraint(i).getForce());
        }
        h = 31 * h + world.getContactCount();
        for (int i = 0; i < emitter.getParticleCount(); i++) {
            h = mix(h, emitter.getX(i));
            h = mix(h, emitter.getY(i));
        }
        h = 31 * h + eventCount;
        return 31 * h + eventHash;
    }

    /**
     * A hash of every body's pose and velocity, in world order.
     *
     * @param world the world
     * @return the hash
     */
    public static long bodyHash(World world) {
        long h = 1125899906842597L;
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            h = mix(h, b.getX());
            h = mix(h, b.getY());
            h = mix(h, b.getAngle());
            h = mix(h, b.getVelocityX());
            h = mix(h, b.getVelocityY());
            h = mix(h, b.getAngularVelocity());
        }
        return h;
    }

    private static long mix(long h, float value) {
        return 31 * h + Float.floatToIntBits(value);
    }
}
