package org.emini.bench.engine;

import com.badlogic.gdx.math.Vector2;
import com.badlogic.gdx.physics.box2d.Body;
import com.badlogic.gdx.physics.box2d.BodyDef;
import com.badlogic.gdx.physics.box2d.Box2D;
import com.badlogic.gdx.physics.box2d.CircleShape;
import com.badlogic.gdx.physics.box2d.FixtureDef;
import com.badlogic.gdx.physics.box2d.PolygonShape;
import com.badlogic.gdx.physics.box2d.Shape;
import com.badlogic.gdx.physics.box2d.World;
import org.emini.harness.scenario.Scenario;

/**
 * libGDX's Box2D extension (gdx-box2d 1.12.1): native Box2D 2.3.1 called through JNI, loaded from the
 * gdx-box2d-platform desktop natives with {@link Box2D#init()}. Same settings as {@link JBox2dEngine}:
 * 8 velocity and 3 position iterations, continuous collision at its default, sleeping off. Metres via
 * {@link PeerScene}. Memory the native side allocates is not seen by JMH's GC profiler.
 */
final class GdxBox2dEngine implements BenchEngine {
    private static final int MAX_POLYGON_VERTICES = 8;
    private World world;
    private Body[] bodies;
    private float dt;
    private PeerParticles<Body> particles;
    private boolean sleeping;

    @Override
    public String id() {
        return "gdx-box2d";
    }

    @Override
    public void build(Scenario scenario) throws UnsupportedSceneException {
        PeerScene scene = PeerScene.of(scenario, "gdx-box2d", MAX_POLYGON_VERTICES);
        Box2D.init();
        dt = (float) scene.timestep;
        world = new World(new Vector2((float) scene.gravityX, (float) scene.gravityY), scene.sleeping);
        sleeping = scene.sleeping;
        bodies = new Body[scene.bodies.size()];
        int i = 0;
        for (PeerScene.PeerBody pb : scene.bodies) {
            BodyDef def = new BodyDef();
            def.type = pb.dynamic ? BodyDef.BodyType.DynamicBody : BodyDef.BodyType.StaticBody;
            def.position.set((float) pb.x, (float) pb.y);
            def.angle = (float) pb.angle;
            def.linearVelocity.set((float) pb.vx, (float) pb.vy);
            def.angularVelocity = (float) pb.omega;
            def.fixedRotation = !pb.rotatable;
            def.gravityScale = pb.gravity ? 1f : 0f;
            def.allowSleep = scene.sleeping && pb.sleepingAllowed;
            Body b = world.createBody(def);
            for (PeerScene.PeerShape part : pb.parts) {
                Shape shape = shape(part);
                FixtureDef fd = new FixtureDef();
                fd.shape = shape;
                fd.density = (float) part.density;
                fd.friction = (float) part.friction;
                fd.restitution = (float) part.restitution;
                b.createFixture(fd);
                shape.dispose();
            }
            bodies[i++] = b;
        }
        particles = new PeerParticles<>(scene.emitters, new Particles());
        for (int k = 0; k < scene.joints.size(); k++) {
            PeerScene.PeerJoint pj = scene.joints.get(k);
            if (pj.fixed) {
                com.badlogic.gdx.physics.box2d.joints.WeldJointDef d = new com.badlogic.gdx.physics.box2d.joints.WeldJointDef();
                d.initialize(bodies[pj.a], bodies[pj.b], new Vector2((float) pj.x, (float) pj.y));
                d.collideConnected = pj.collide;
                world.createJoint(d);
            } else {
                com.badlogic.gdx.physics.box2d.joints.RevoluteJointDef d = new com.badlogic.gdx.physics.box2d.joints.RevoluteJointDef();
                d.initialize(bodies[pj.a], bodies[pj.b], new Vector2((float) pj.x, (float) pj.y));
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
            circle.setRadius((float) PeerScene.PARTICLE_RADIUS);
            def.type = BodyDef.BodyType.DynamicBody;
            def.fixedRotation = true;
            def.allowSleep = false;
            fd.shape = circle;
            fd.density = 1f;
            fd.friction = 0f;
            fd.filter.categoryBits = (short) PeerScene.PARTICLE_CATEGORY;
        }

        @Override
        public Body create(PeerScene.PeerEmitter e, double x, double y, double vx, double vy) {
            def.position.set((float) x, (float) y);
            def.linearVelocity.set((float) vx, (float) vy);
            def.gravityScale = (float) e.gravityScale;
            Body b = world.createBody(def);
            fd.restitution = (float) e.restitution;
            fd.filter.maskBits = (short) (e.collide ? PeerScene.PARTICLE_MASK : 0);
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
            c.setRadius((float) sh.radius);
            c.setPosition(new Vector2((float) sh.cx, (float) sh.cy));
            return c;
        }
        float[] v = new float[sh.xy.length];
        for (int k = 0; k < v.length; k++) {
            v[k] = (float) sh.xy[k];
        }
        PolygonShape p = new PolygonShape();
        p.set(v);
        return p;
    }

    @Override
    public void tick() {
        if (particles.any()) {
            particles.beforeStep(dt);
        }
        world.step(dt, JBox2dEngine.VELOCITY_ITERATIONS, JBox2dEngine.POSITION_ITERATIONS);
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
            Vector2 p = bodies[i].getPosition();
            PeerScene.putPose(out, i, p.x, p.y, bodies[i].getAngle());
        }
    }

    @Override
    public void speeds(double[] out) {
        for (int i = 0; i < bodies.length; i++) {
            Vector2 v = bodies[i].getLinearVelocity();
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
            n += b.getType() == BodyDef.BodyType.DynamicBody && !b.isAwake() ? 1 : 0;
        }
        return n;
    }

    @Override
    public String settings() {
        return "metres (20 px = 1 m); timestep " + dt + " s; " + JBox2dEngine.VELOCITY_ITERATIONS + " velocity + "
            + JBox2dEngine.POSITION_ITERATIONS + " position iterations (Box2D's recommendation); "
            + JBox2dEngine.sleepSettings(sleeping) + "; native Box2D 2.3.1 via JNI"
            + (particles.any() ? "; " + JBox2dEngine.PARTICLES : "");
    }

    @Override
    public void close() {
        if (world != null) {
            world.dispose();
        }
        world = null;
        bodies = null;
    }
}
