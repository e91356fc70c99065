package org.emini.bench.engine;

import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.Settings;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.World;
import org.emini.harness.scenario.Scenario;

/**
 * dyn4j 5.0.2 at its default solver settings (10 velocity and 10 position iterations, continuous
 * collision for bullets against static bodies, warm starting), with at-rest detection (sleeping) off
 * so a settled scene keeps being simulated, as in every engine here, unless the scene turns sleeping
 * on ({@code world.sleeping}: then dyn4j's own at-rest tolerances). Metres via {@link PeerScene}.
 */
final class Dyn4jEngine implements BenchEngine {
    private World<Body> world;
    private Body[] bodies;
    private PeerScene scene;
    private PeerParticles<Body> particles;

    @Override
    public String id() {
        return "dyn4j";
    }

    @Override
    public void build(Scenario scenario) throws UnsupportedSceneException {
        scene = PeerScene.of(scenario, "dyn4j", Integer.MAX_VALUE);
        world = new World<>();
        Settings s = world.getSettings();
        s.setStepFrequency(scene.timestep);
        s.setAtRestDetectionEnabled(scene.sleeping);
        world.setGravity(scene.gravityX, scene.gravityY);
        bodies = new Body[scene.bodies.size()];
        int i = 0;
        for (PeerScene.PeerBody pb : scene.bodies) {
            Body b = new Body();
            for (PeerScene.PeerShape sh : pb.parts) {
                Convex c;
                if (sh.circle) {
                    c = Geometry.createCircle(sh.radius);
                    c.translate(sh.cx, sh.cy);
                } else {
                    Vector2[] v = new Vector2[sh.vertexCount()];
                    for (int k = 0; k < v.length; k++) {
                        v[k] = new Vector2(sh.xy[2 * k], sh.xy[2 * k + 1]);
                    }
                    c = Geometry.createPolygon(v);
                }
                b.addFixture(c, sh.density, sh.friction, sh.restitution);
            }
            if (!pb.dynamic) {
                b.setMass(MassType.INFINITE);
            } else {
                b.setMass(pb.rotatable ? MassType.NORMAL : MassType.FIXED_ANGULAR_VELOCITY);
            }
            b.rotate(pb.angle);
            b.translate(pb.x, pb.y);
            b.setLinearVelocity(pb.vx, pb.vy);
            b.setAngularVelocity(pb.omega);
            if (!pb.gravity) {
                b.setGravityScale(0);
            }
            b.setAtRestDetectionEnabled(scene.sleeping && pb.sleepingAllowed);
            world.addBody(b);
            bodies[i++] = b;
        }
        particles = new PeerParticles<>(scene.emitters, new Particles());
        for (int k = 0; k < scene.joints.size(); k++) {
            PeerScene.PeerJoint pj = scene.joints.get(k);
            Vector2 at = new Vector2(pj.x, pj.y);
            org.dyn4j.dynamics.joint.Joint<Body> j;
            if (pj.fixed) {
                j = new org.dyn4j.dynamics.joint.WeldJoint<>(bodies[pj.a], bodies[pj.b], at);
            } else {
                org.dyn4j.dynamics.joint.RevoluteJoint<Body> r = new org.dyn4j.dynamics.joint.RevoluteJoint<>(bodies[pj.a], bodies[pj.b], at);
                for (PeerScene.PeerMotor pm : scene.motors) {
                    if (pm.joint == k) {
                        motor(r, pm);
                    }
                }
                j = r;
            }
            j.setCollisionAllowed(pj.collide);
            world.addJoint(j);
        }
    }

    /**
     * The joint's motor. {@link PeerScene.PeerMotor#speed} is ω_b − ω_a (Box2D's sense); dyn4j's
     * revolute motor speed is ω_a − ω_b (body 1 minus body 2), so it is negated (AdaptersTest reads
     * the driven body's ω back in every engine).
     */
    private static void motor(org.dyn4j.dynamics.joint.RevoluteJoint<Body> r, PeerScene.PeerMotor pm) {
        r.setMotorEnabled(true);
        r.setMotorSpeed(-pm.speed);
        r.setMaximumMotorTorqueEnabled(true);
        r.setMaximumMotorTorque(pm.maxTorque);
    }

    /** Particles as small circle bodies meeting the scene's bodies only (a category filter). */
    private final class Particles implements PeerParticles.Physics<Body> {
        @Override
        public Body create(PeerScene.PeerEmitter e, double x, double y, double vx, double vy) {
            Body b = new Body();
            org.dyn4j.dynamics.BodyFixture f = b.addFixture(Geometry.createCircle(PeerScene.PARTICLE_RADIUS), 1.0, 0.0, e.restitution);
            f.setFilter(new org.dyn4j.collision.CategoryFilter(PeerScene.PARTICLE_CATEGORY, e.collide ? PeerScene.PARTICLE_MASK : 0));
            b.setMass(MassType.FIXED_ANGULAR_VELOCITY);
            b.translate(x, y);
            b.setLinearVelocity(vx, vy);
            b.setGravityScale(e.gravityScale);
            b.setAtRestDetectionEnabled(false);
            world.addBody(b);
            return b;
        }

        @Override
        public void destroy(Body b) {
            world.removeBody(b);
        }

        @Override
        public double x(Body b) {
            return b.getTransform().getTranslationX();
        }

        @Override
        public double y(Body b) {
            return b.getTransform().getTranslationY();
        }
    }

    @Override
    public void tick() {
        if (particles.any()) {
            particles.beforeStep(scene.timestep);
        }
        world.step(1);
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
            // The body's origin is its centroid here (checked by PeerScene), as in the scene.
            PeerScene.putPose(out, i, bodies[i].getTransform().getTranslationX(),
                bodies[i].getTransform().getTranslationY(), bodies[i].getTransform().getRotationAngle());
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
        if (!world.getSettings().isAtRestDetectionEnabled()) {
            return -1;
        }
        int n = 0;
        for (Body b : bodies) {
            n += !b.getMass().isInfinite() && b.isAtRest() ? 1 : 0;
        }
        return n;
    }

    @Override
    public String settings() {
        Settings s = world.getSettings();
        return "metres (20 px = 1 m); timestep " + s.getStepFrequency() + " s; "
            + s.getVelocityConstraintSolverIterations() + " velocity + " + s.getPositionConstraintSolverIterations()
            + " position iterations (defaults); continuous detection " + s.getContinuousDetectionMode()
            + (s.isAtRestDetectionEnabled() ? String.format(java.util.Locale.ROOT, "; at-rest detection (sleeping) on at "
                + "dyn4j's tolerances (%.2f m/s = %.1f px/s, %.1f deg/s, %.1f s)", s.getMaximumAtRestLinearVelocity(),
                s.getMaximumAtRestLinearVelocity() * PeerScene.PX_PER_M, Math.toDegrees(s.getMaximumAtRestAngularVelocity()),
                s.getMinimumAtRestTime()) : "; at-rest detection off")
            + (particles.any() ? "; " + JBox2dEngine.PARTICLES : "");
    }

    @Override
    public void close() {
        world = null;
        bodies = null;
    }
}
