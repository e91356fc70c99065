package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.emini.constraint.Joint;
import org.emini.constraint.Motor;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.Landscape;
import org.emini.world.World;
import org.emini.harness.build.ConnectedPairs;
import org.emini.event.Event;
import org.emini.particle.ParticleEmitter;

/**
 * Builds a recipe's engine world through the public API, in the harness's order and with its
 * arithmetic (world settings, bodies, simulation area, landscape, joints, springs, motors, particles),
 * so that a recipe and its scene file give the same world; then what a scene cannot say: external
 * forces, events with their listener, and removals during a tick.
 */
public final class RecipeBuilder {
    private RecipeBuilder() {
    }

    /** Builds the world. Engine refusals (IllegalArgumentException) pass through. */
    public static FuzzWorld build(Recipe r) {
        World world = new World();
        world.setSleepingEnabled(r.sleeping);
        world.setTimestep(r.timestep());
        world.setConstraintIterations(r.iterations);
        world.setConstraintIterationDynamic(r.dynamicIterations);
        world.setGravity(r.gravityX, r.gravityY);
        world.setDampingLateral(r.dampingLateral);
        world.setDampingRotational(r.dampingRotational);
        ShapeBuilder shapes = new ShapeBuilder(r);
        Body[] bodies = new Body[r.bodies.size()];
        Map<Integer, Body> byId = new HashMap<>();
        for (int i = 0; i < bodies.length; i++) {
            BodyRecipe b = r.bodies.get(i);
            bodies[i] = body(b, shapes);
            world.addBody(bodies[i]);
            byId.put(b.id, bodies[i]);
        }
        if (r.area != null) {
            if (r.area.range) {
                world.setSimulationArea(r.area.minX, r.area.maxX);
            } else {
                world.setSimulationArea(r.area.minX, r.area.minY, r.area.maxX, r.area.maxY);
            }
        }
        if (!r.segments.isEmpty()) {
            Landscape land = world.getLandscape();
            land.setFriction(r.landscapeFriction);
            land.setElasticity(r.landscapeElasticity);
            for (SegmentRecipe s : r.segments) {
                land.addSegment(s.x1, s.y1, s.x2, s.y2, s.face);
            }
        }
        Map<String, Constraint> constraints = constraints(r, world, byId);
        List<ParticleEmitter> emitters = new ArrayList<>();
        for (EmitterRecipe e : r.emitters) {
            emitters.add(emitter(e, byId));
            world.addParticleEmitter(emitters.get(emitters.size() - 1));
        }
        for (ForceRecipe f : r.forces) {
            world.addExternalForce(new FuzzForce(f, f.kind == ForceRecipe.Kind.wind ? null : need(byId, f.body)));
        }
        for (EventRecipe e : r.events) {
            world.addEvent(event(e, byId, shapes, constraints));
        }
        FuzzListener listener = removals(r, world, byId);
        return new FuzzWorld(r, world, bodies, byId, constraints, emitters, listener);
    }

    private static Body body(BodyRecipe b, ShapeBuilder shapes) {
        Body body = new Body(b.x, b.y, shapes.shape(b.shape), b.dynamic);
        body.setRotatable(b.rotatable);
        body.setInteracting(b.interacting);
        body.setGravityAffected(b.gravity);
        for (int k = 0; k < 32; k++) {
            if ((b.layers & (1 << k)) != 0) {
                body.addCollisionLayer(k);
            }
        }
        body.setCategoryBits(b.categories);
        body.setMaskBits(b.mask);
        body.setGroupIndex(b.group);
        body.setSensor(b.sensor);
        body.setSleepingAllowed(b.sleepingAllowed);
        body.setAngle(b.angle);
        if (b.dynamic) {
            // A static body refuses a velocity (the original ignored it).
            body.setVelocity(b.vx, b.vy);
            body.setAngularVelocity(b.omega);
        }
        body.setBullet(b.bullet);
        return body;
    }

    private static Map<String, Constraint> constraints(Recipe r, World world, Map<Integer, Body> byId) {
        Map<String, Constraint> made = new LinkedHashMap<>();
        List<Body[]> apart = new ArrayList<>();
        for (int i = 0; i < r.joints.size(); i++) {
            JointRecipe j = r.joints.get(i);
            Body a = need(byId, j.a);
            Body b = need(byId, j.b);
            Joint joint = j.atPoint ? Joint.atWorldPoint(a, b, j.x, j.y, j.fixed)
                    : new Joint(a, b, j.ax, j.ay, j.bx, j.by, j.fixed);
            if (!j.collide) {
                apart.add(new Body[] {a, b});
            }
            world.addConstraint(joint);
            made.put("joint:" + j.id, joint);
        }
        for (int i = 0; i < r.springs.size(); i++) {
            SpringRecipe s = r.springs.get(i);
            Body a = need(byId, s.a);
            Body b = need(byId, s.b);
            Spring spring = s.restLength >= 0f ? new Spring(a, b, s.ax, s.ay, s.bx, s.by, s.restLength)
                    : new Spring(a, b, s.ax, s.ay, s.bx, s.by);
            if (s.hertz > 0f) {
                spring.setFrequency(s.hertz, s.dampingRatio);
            } else if (s.stiffness > 0f) {
                spring.setCoefficient(s.stiffness);
                spring.setDamping(s.damping);
            }
            if (!s.collide) {
                apart.add(new Body[] {a, b});
            }
            world.addConstraint(spring);
            made.put("spring:" + s.id, spring);
        }
        // As a scene's builder does.
        ConnectedPairs.applyTo(world, apart);
        float dt = world.getTimestep();
        for (MotorRecipe m : r.motors) {
            Body body = need(byId, m.body);
            float max = m.maxImpulse / dt;
            Motor motor = m.rotational ? new Motor(body, m.omega, max) : new Motor(body, m.vx, m.vy, max);
            motor.setRelative(m.relative);
            motor.setOrthogonal(m.orthogonal);
            world.addConstraint(motor);
            made.put("motor:" + m.id, motor);
        }
        return made;
    }

    private static ParticleEmitter emitter(EmitterRecipe r, Map<Integer, Body> byId) {
        ParticleEmitter e = new ParticleEmitter(r.maxCount, r.body >= 0 ? need(byId, r.body) : null);
        e.setEmitSegment(r.x1, r.y1, r.x2, r.y2);
        e.setCreationRate(r.rate, r.rateSpread);
        e.setLifetime(r.lifetime, r.lifetimeSpread);
        e.setSpeed(r.speed, r.speedSpread);
        e.setAngle((float) Math.toRadians(r.angleDeg), (float) Math.toRadians(r.angleSpreadDeg));
        e.setAxesFixed(r.axesFixed);
        e.setElasticity(r.elasticity);
        e.setGravityFactor(r.gravityFactor);
        e.setDamping(r.damping);
        e.setCanCollide(r.collide);
        e.setSeed(r.seed);
        return e;
    }

    private static Event event(EventRecipe e, Map<Integer, Body> byId, ShapeBuilder shapes, Map<String, Constraint> constraints) {
        Body body = e.body >= 0 ? need(byId, e.body) : null;
        org.emini.shape.Shape shape = e.shape >= 0 ? shapes.shape(e.shape) : null;
        Event event = switch (e.type) {
            case Event.POSITION -> Event.createPositionEvent(body, shape, e.p1, e.p2, e.p3, e.p4);
            case Event.VELOCITY -> Event.createVelocityEvent(body, shape, e.p1, e.p2);
            case Event.ANGLE -> Event.createAngleEvent(body, shape, e.p1, e.p2);
            case Event.ANGULAR_VELOCITY -> Event.createAngularVelocityEvent(body, shape, e.p1, e.p2);
            case Event.COLLISION -> Event.createCollisionEvent(body, shape, e.p1 != 0f, e.p2 != 0f, e.p3 != 0f, e.p4 != 0f);
            case Event.RELATIVE_COLLISION -> Event.createRelativeCollisionEvent(body, shape, e.p1, e.p2);
            case Event.SENSOR -> Event.createSensorEvent(body, shape, need(byId, e.sensor));
            case Event.CONSTRAINT_FORCE -> Event.createConstraintForceEvent(
                    e.constraintKind == null ? null : constraints.get(e.constraintKind + ":" + e.constraint), e.p1, e.p2);
            default -> throw new IllegalArgumentException("unknown event type " + e.type);
        };
        event.setTriggerOnce(e.triggerOnce);
        return event;
    }

    /** Constraint removals are added last; listener removals need an event that always fires. */
    private static FuzzListener removals(Recipe r, World world, Map<Integer, Body> byId) {
        List<Body> viaListener = new ArrayList<>();
        List<Integer> ticks = new ArrayList<>();
        for (RemovalRecipe m : r.removals) {
            if (m.via == RemovalRecipe.Via.constraint) {
                world.addConstraint(new RemovingConstraint(world, need(byId, m.body), m.tick));
            } else {
                viaListener.add(need(byId, m.body));
                ticks.add(m.tick);
            }
        }
        if (!viaListener.isEmpty()) {
            world.addEvent(Event.createPositionEvent(null, null, -Float.MAX_VALUE, -Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE));
        }
        if (!r.listener && viaListener.isEmpty()) {
            return null;
        }
        int[] at = ticks.stream().mapToInt(Integer::intValue).toArray();
        FuzzListener listener = new FuzzListener(world, viaListener.toArray(new Body[0]), at);
        world.setPhysicsEventListener(listener);
        return listener;
    }

    private static Body need(Map<Integer, Body> byId, int id) {
        Body b = byId.get(id);
        if (b == null) {
            throw new IllegalArgumentException("the recipe has no body with id " + id);
        }
        return b;
    }
}
