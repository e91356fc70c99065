package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.math.EMath;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Particles never tunnel: each tick's motion is tested as a segment, so a closed box of bodies
 * holds particles that cross many times its wall thickness per tick, for a long run, whatever the
 * elasticity, the box's rotation and the obstacles inside it.
 */
class ParticleContainmentTest {
    /**
     * A 400 px box of 2 px walls, a spray from its centre at the given speed ± half of it in every
     * direction (up to 30,000 px/s: 1,500 px, almost four box widths, per tick), 30 s.
     */
    @ParameterizedTest
    @CsvSource({"4000, 1, 0", "4000, 0.5, 0.3", "20000, 1, 0.7853982", "20000, 0, 0", "600, 0.8, 1"})
    void fastParticlesNeverLeaveAClosedBoxOfBodies(float speed, float elasticity, float angle) {
        World world = new World();
        ParticleScenes.box(world, 200f, 2f, angle);
        ParticleEmitter e = ParticleScenes.spray(2000, 1000f, 2f, speed, speed);
        e.setElasticity(elasticity);
        world.addParticleEmitter(e);
        int seen = 0;
        for (int t = 0; t < 600; t++) {
            world.tick();
            assertEquals(0, ParticleScenes.countOutsideBox(e, 200f, angle), "tick " + t);
            seen += e.getParticleCount();
        }
        assertTrue(seen > 500 * 2000, "the box was full: " + seen);
    }

    /** Obstacles inside the box: particles end every tick outside all of them, and inside the box. */
    @Test
    void particlesEndEveryTickOutsideEveryStaticBody() {
        World world = new World();
        ParticleScenes.box(world, 200f, 4f, 0.2f);
        Body[] obstacles = {
            new Body(-100f, -80f, Shape.createCircle(30f), false),
            new Body(90f, 60f, Shape.createRegularPolygon(40f, 5), false),
            new Body(-60f, 110f, Shape.createRectangle(120f, 3f), false),
            new Body(120f, -120f, Shape.createRectangle(8f, 8f), false),
        };
        obstacles[1].setAngle(0.4f);
        obstacles[2].setAngle(-0.6f);
        for (Body b : obstacles) {
            world.addBody(b);
        }
        ParticleEmitter e = ParticleScenes.spray(3000, 2000f, 1.5f, 3000f, 6000f);
        e.setEmitSegment(-20f, 0f, 20f, 0f);
        world.addParticleEmitter(e);
        for (int t = 0; t < 400; t++) {
            world.tick();
            assertEquals(0, ParticleScenes.countOutsideBox(e, 200f, 0.2f), "tick " + t);
            for (Body b : obstacles) {
                assertEquals(0, countInside(e, b), "tick " + t + ", " + b);
            }
        }
    }

    /**
     * Crates and balls tumbling in the box and settling on its floor, pressed a little into it by
     * the solver: particles squeezed between a body and a wall end up on the wall's side.
     */
    @Test
    void particlesStayInABoxFullOfTumblingBodies() {
        World world = new World();
        ParticleScenes.box(world, 300f, 10f, 0f);
        ParticleScenes.cratesAndBalls(world, 40, -260f, 13f, 200f);
        ParticleEmitter e = ParticleScenes.spray(5000, 5000f, 1000f, 800f, 800f);
        e.setEmitSegment(-100f, -250f, 100f, -250f);
        e.setElasticity(0.9f);
        world.addParticleEmitter(e);
        for (int t = 0; t < 600; t++) {
            world.tick();
            assertEquals(0, ParticleScenes.countOutsideBox(e, 300f, 0f), "tick " + t);
        }
        assertEquals(5000, e.getParticleCount());
    }

    /** A concave U of three boxes, turning inside the box: particles end every tick outside all its parts. */
    @Test
    void particlesEndEveryTickOutsideATurningConcaveMultiShape() {
        World world = new World();
        world.setGravity(0f, 0f);
        ParticleScenes.box(world, 200f, 2f, 0f);
        Shape u = Shape.createMultiShape(
            Shape.createPolygon(-60f, 20f, 60f, 20f, 60f, 30f, -60f, 30f),
            Shape.createPolygon(-60f, -50f, -50f, -50f, -50f, 20f, -60f, 20f),
            Shape.createPolygon(50f, -50f, 60f, -50f, 60f, 20f, 50f, 20f));
        Body cup = new Body(0f, 0f, u, true);
        cup.setGravityAffected(false);
        cup.setAngularVelocity(1.5f);
        world.addBody(cup);
        ParticleEmitter e = ParticleScenes.spray(3000, 1500f, 2f, 500f, 400f);
        e.setEmitSegment(-150f, -150f, 150f, -150f);
        world.addParticleEmitter(e);
        for (int t = 0; t < 300; t++) {
            world.tick();
            assertEquals(0, ParticleScenes.countOutsideBox(e, 200f, 0f), "tick " + t);
            assertEquals(0, countInside(e, cup), "tick " + t);
        }
    }

    /**
     * A dynamic body outside the simulation area is frozen with its velocity: particles see it
     * stand still, so one that hits the face it would move towards bounces as off a wall.
     */
    @Test
    void aFrozenBodyStandsStillForParticles() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body frozen = new Body(500f, 0f, Shape.createRectangle(20f, 20f), true);
        frozen.setVelocity(300f, 0f);
        world.addBody(frozen);
        world.setSimulationArea(-100f, -100f, 100f, 100f);
        ParticleEmitter e = ParticleScenes.one(world, 530f, 0f, -100f, 0f);
        ParticleScenes.run(world, 10);
        assertEquals(500f, frozen.getX(), 0f);
        assertEquals(100f, e.getVelocityX(0), 1e-3f, "elastic bounce off a still face");
    }

    /** A bar turning at 6 rad/s (tip speed 600 px/s) inside the box bats particles but never lets one out. */
    @Test
    void aTurningBarInsideTheBoxKeepsParticlesOutOfItAndInTheBox() {
        World world = new World();
        world.setGravity(0f, 0f);
        ParticleScenes.box(world, 200f, 2f, 0f);
        Body bar = new Body(0f, 0f, Shape.createRectangle(200f, 6f), true);
        bar.setAngularVelocity(6f);
        world.addBody(bar);
        ParticleEmitter e = ParticleScenes.spray(3000, 1000f, 3f, 150f, 100f);
        e.setEmitSegment(-150f, -150f, 150f, -150f);
        e.setAngle(EMath.PI / 2f, 1f);
        world.addParticleEmitter(e);
        int inside = 0;
        int total = 0;
        for (int t = 0; t < 400; t++) {
            world.tick();
            assertEquals(0, ParticleScenes.countOutsideBox(e, 200f, 0f), "tick " + t);
            inside += countInside(e, bar);
            total += e.getParticleCount();
        }
        assertEquals(6f, bar.getAngularVelocity(), 1e-4f, "particles push nothing");
        assertEquals(0, inside, "particle-ticks inside the bar, of " + total);
    }

    private static int countInside(ParticleEmitter e, Body b) {
        int inside = 0;
        for (int i = 0; i < e.getParticleCount(); i++) {
            float lx = b.toLocalX(e.getX(i), e.getY(i));
            float ly = b.toLocalY(e.getX(i), e.getY(i));
            if (contains(b.getShape(), lx, ly)) {
                inside++;
            }
        }
        return inside;
    }

    private static boolean contains(Shape shape, float x, float y) {
        if (shape instanceof org.emini.shape.MultiShape) {
            org.emini.shape.MultiShape m = (org.emini.shape.MultiShape) shape;
            for (int i = 0; i < m.getShapeCount(); i++) {
                if (contains(m.getShape(i), x, y)) {
                    return true;
                }
            }
            return false;
        }
        if (shape instanceof org.emini.shape.Circle) {
            org.emini.shape.Circle c = (org.emini.shape.Circle) shape;
            float dx = x - c.getCenterX();
            float dy = y - c.getCenterY();
            return dx * dx + dy * dy < c.getRadius() * c.getRadius();
        }
        org.emini.shape.Polygon p = (org.emini.shape.Polygon) shape;
        for (int i = 0; i < p.getVertexCount(); i++) {
            if (p.getNormalX(i) * (x - p.getVertexX(i)) + p.getNormalY(i) * (y - p.getVertexY(i)) >= 0f) {
                return false;
            }
        }
        return true;
    }
}
