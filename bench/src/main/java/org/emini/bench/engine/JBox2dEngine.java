package org.emini.bench.engine;

import org.emini.harness.scenario.Scenario;
import org.jbox2d.collision.shapes.CircleShape;
import org.jbox2d.collision.shapes.PolygonShape;
import org.jbox2d.collision.shapes.Shape;
import org.jbox2d.common.Settings;
import org.jbox2d.common.Vec2;
import org.jbox2d.dynamics.Body;
import org.jbox2d.dynamics.BodyDef;
import org.jbox2d.dynamics.BodyType;
import org.jbox2d.dynamics.FixtureDef;
import org.jbox2d.dynamics.World;

/**
 * JBox2D 2.2.1.1 (a Java port of Box2D 2.2) with Box2D's recommended 8 velocity and 3 position
 * iterations, continuous collision at its default (dynamic against static), warm starting on, and
 * sleeping off so a settled scene keeps being simulated, unless the scene turns sleeping on
 * ({@code world.sleeping}: then Box2D's own tolerances). Metres via {@link PeerScene}.
 */
final class JBox2dEngine implements BenchEngine {
    /** Box2D's recommended velocity iterations. */
    static final int VELOCITY_ITERATIONS = 8;
    /** Box2D's recommended position iterations. */
    static final int POSITION_ITERATIONS = 3;

    /** How the peers make particles, for the settings line. */
    static final String PARTICLES = "particles as circle bodies of 0.1 m, fixed rotation, no friction, meeting the scene's "
        + "bodies but not each other (collision filter), created as emitted and destroyed when their lifetime ends";

    private World world;
    private Body[] bodies;
    private float dt;
    private boolean sleeping;
    private PeerParticles<Body> particles;

    @Override
    public String id() {
        return "jbox2d";
    }

    @Override
    public void build(Scenario scenario) throws UnsupportedSceneException {
        PeerScene scene = PeerScene.of(scenario, "jbox2d", Settings.maxPolygonVertices);
        dt = (float) scene.timestep;
        world = new World(new Vec2((float) scene.gravityX, (float) scene.gravityY));
        world.setAllowSleep(scene.sleeping);
        sleeping = scene.sleeping;
        bodies = new Body[scene.bodies.size()];
        int i = 0;
        for (PeerScene.PeerBody pb : scene.bodies) {
            BodyDef def = new BodyDef();
            def.type = pb.dynamic ? BodyType.DYNAMIC : BodyType.STATIC;
            def.position.set((float) pb.x, (float) pb.y);
            def.angle = (float) pb.angle;
            def.linearVelocity.set((float) pb.vx, (float) pb.vy);
            def.angularVelocity = (float) pb.omega;
            def.fixedRotation = !pb.rotatable;
            def.gravityScale = pb.gravity ? 1f : 0f;
            def.allowSleep = scene.sleeping && pb.sleepingAllowed;
            Body b = world.createBody(def);
            for (PeerScene.PeerShape part : pb.parts) {
                FixtureDef fd = new FixtureDef();
                fd.shape = shape(part);
                fd.density = (float) part.density;
                fd.friction = (float) part.friction;
                fd.restitution = (float) part.restitution;
                b.createFixture(fd);
            }
            bodies[i++] = b;
        }
        particles = new PeerParticles<>(scene.emitters, new Particles());
        for (int k = 0; k < scene.joints.size(); k++) {
            PeerScene.PeerJoint pj = scene.joints.get(k);
            if (pj.fixed) {
                org.jbox2d.dynamics.joints.WeldJointDef d = new org.jbox2d.dynamics.joints.WeldJointDef();
                d.initialize(bodies[pj.a], bodies[pj.b], new Vec2((float) pj.x, (float) pj.y));
                d.collideConnected = pj.collide;
                world.createJoint(d);
            } else {
                org.jbox2d.dynamics.joints.RevoluteJointDef d = new org.jbox2d.dynamics.joints.RevoluteJointDef();
                d.initialize(bodies[pj.a], bodies[pj.b], new Vec2((float) pj.x, (float) pj.y));
                d.collideConnected = pj.collide;
                for (PeerScene.PeerMotor pm : scene.motors) {
                    if (pm.joint == k) {
                        d.enableMotor = true;
                        d.motorSpeed = (float) pm.speed;
                        d.maxMotorTorque = (float) pm.maxTorque;
                    }
                }
                world.createJoint(d);
            }
        }
    }

    /** Particles as small circle bodies meeting the scene's bodies only (categories and masks). */
    private final class Particles implements PeerParticles.Physics<Body> {
        private final CircleShape circle = new CircleShape();
        private final BodyDef def = new BodyDef();
        private final FixtureDef fd = new FixtureDef();

        Particles() {
            circle.m_radius = (float) PeerScene.PARTICLE_RADIUS;
            def.type = BodyType.DYNAMIC;
            def.fixedRotation = true;
            def.allowSleep = false;
            fd.shape = circle;
            fd.density = 1f;
            fd.friction = 0f;
            fd.filter.categoryBits = PeerScene.PARTICLE_CATEGORY;
        }

        @Override
        public Body create(PeerScene.PeerEmitter e, double x, double y, double vx, double vy) {
            def.position.set((float) x, (float) y);
            def.linearVelocity.set((float) vx, (float) vy);
            def.gravityScale = (float) e.gravityScale;
            Body b = world.createBody(def);
            fd.restitution = (float) e.restitution;
            fd.filter.maskBits = e.collide ? PeerScene.PARTICLE_MASK : 0;
            b.createFixture(fd);
            return b;
        }

        @Override
        public void destroy(Body b) {
            world.destroyBody(b);
        }

        @Override
        public double x(Body b) {
            return b.getPosition().x;
        }

        @Override
        public double y(Body b) {
            return b.getPosition().y;
        }
    }

    private static Shape shape(PeerScene.PeerShape sh) {
        if (sh.circle) {
            CircleShape c = new CircleShape();
            c.m_radius = (float) sh.radius;
            c.m_p.set((float) sh.cx, (float) sh.cy);
            return c;
        }
        Vec2[] v = new Vec2[sh.vertexCount()];
        for (int k = 0; k < v.length; k++) {
            v[k] = new Vec2((float) sh.xy[2 * k], (float) sh.xy[2 * k + 1]);
        }
        PolygonShape p = new PolygonShape();
        p.set(v, v.length);
        return p;
    }

    @Override
    public void tick() {
        if (particles.any()) {
            particles.beforeStep(dt);
        }
        world.step(dt, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    }

    @Override
    public int particleCount() {
        return particles.count();
    }

    @Override
    public void particlePositions(double[] out) {
        particles.positions(out);
    }

    @Override
    public int bodyCount() {
        return bodies.length;
    }

    @Override
    public void poses(double[] out) {
        for (int i = 0; i < bodies.length; i++) {
            Vec2 p = bodies[i].getPosition();
            PeerScene.putPose(out, i, p.x, p.y, bodies[i].getAngle());
        }
    }

    @Override
    public void speeds(double[] out) {
        for (int i = 0; i < bodies.length; i++) {
            Vec2 v = bodies[i].getLinearVelocity();
            out[i] = PeerScene.speedPx(v.x, v.y);
        }
    }

    @Override
    public void angularVelocities(double[] out) {
        for (int i = 0; i < bodies.length; i++) {
            out[i] = -bodies[i].getAngularVelocity();
        }
    }

    @Override
    public int sleepingCount() {
        if (!sleeping) {
            return -1;
        }
        int n = 0;
        for (Body b : bodies) {
            n += b.getType() == BodyType.DYNAMIC && !b.isAwake() ? 1 : 0;
        }
        return n;
    }

    @Override
    public String settings() {
        return "metres (20 px = 1 m); timestep " + dt + " s; " + VELOCITY_ITERATIONS + " velocity + "
            + POSITION_ITERATIONS + " position iterations (Box2D's recommendation); " + sleepSettings(sleeping)
            + (particles.any() ? "; " + PARTICLES : "");
    }

    /** The sleeping part of a Box2D adapter's settings line (Box2D 2.2 and 2.3 share the constants). */
    static String sleepSettings(boolean on) {
        return on ? String.format(java.util.Locale.ROOT, "sleeping on at Box2D's tolerances (%.2f m/s = %.1f px/s, "
            + "%.1f deg/s, %.1f s)", Settings.linearSleepTolerance, Settings.linearSleepTolerance * PeerScene.PX_PER_M,
            Math.toDegrees(Settings.angularSleepTolerance), Settings.timeToSleep) : "sleeping off";
    }

    @Override
    public void close() {
        world = null;
        bodies = null;
    }
}
