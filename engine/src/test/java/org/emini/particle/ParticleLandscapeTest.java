package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.dynamics.Landscape;
import org.emini.world.World;
import org.emini.math.EMath;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Particles bounce off the landscape from either side (faces do not matter to particles), and a
 * closed chain of landscape segments holds fast particles for good, joints included.
 */
class ParticleLandscapeTest {
    /** A closed regular polygon of n segments around the origin, radius r, first corner at angle a. */
    static Landscape ring(World world, int n, float r, float a) {
        Landscape land = world.getLandscape();
        for (int i = 0; i < n; i++) {
            float a0 = a + EMath.TWO_PI * i / n;
            float a1 = a + EMath.TWO_PI * (i + 1) / n;
            land.addSegment(r * EMath.cos(a0), r * EMath.sin(a0), r * EMath.cos(a1), r * EMath.sin(a1));
        }
        return land;
    }

    /** Whether a point is inside a closed convex landscape: on the same side of every segment as the origin. */
    static boolean encloses(Landscape land, float x, float y) {
        for (int i = 0; i < land.getSegmentCount(); i++) {
            float sx = land.getStartX(i);
            float sy = land.getStartY(i);
            float ex = land.getEndX(i) - sx;
            float ey = land.getEndY(i) - sy;
            float origin = ex * (0f - sy) - ey * (0f - sx);
            float point = ex * (y - sy) - ey * (x - sx);
            if (origin * point <= 0f) {
                return false;
            }
        }
        return true;
    }

    private static void assertEnclosed(Landscape land, ParticleEmitter e, int tick) {
        for (int i = 0; i < e.getParticleCount(); i++) {
            assertTrue(encloses(land, e.getX(i), e.getY(i)), "tick " + tick + ": (" + e.getX(i) + ", " + e.getY(i) + ")");
        }
    }

    @ParameterizedTest
    @CsvSource({"0, 300, 0.5, 0", "0, -300, 0.5, 1", "0.4, 250, 1, 2", "-1.2, 250, 0, 0"})
    void aSegmentReflectsTheNormalVelocityFromEitherSide(float tilt, float speed, float elasticity, int face) {
        World world = new World();
        world.setGravity(0f, 0f);
        float c = EMath.cos(tilt);
        float s = EMath.sin(tilt);
        // A segment through the origin along (c, s), faced or not; the particle comes along its normal (−s, c).
        world.getLandscape().addSegment(-500f * c, -500f * s, 500f * c, 500f * s, face);
        float sign = Math.signum(speed);
        float start = -sign * 100f;
        ParticleEmitter e = ParticleScenes.one(world, -s * start + 30f * c, c * start + 30f * s, -s * speed, c * speed);
        e.setElasticity(elasticity);
        ParticleScenes.run(world, 20);
        float vn = -s * e.getVelocityX(0) + c * e.getVelocityY(0);
        float vt = c * e.getVelocityX(0) + s * e.getVelocityY(0);
        assertEquals(-speed * elasticity, vn, 1e-2f);
        assertEquals(0f, vt, 1e-2f, "no tangential speed before, none after");
        float side = -s * e.getX(0) + c * e.getY(0);
        assertTrue(side * start > 0f, "back on its own side: " + side);
    }

    /** A 24-segment ring of radius 200: sprays up to 30,000 px/s (1,500 px a tick) stay inside. */
    @ParameterizedTest
    @CsvSource({"4000, 1, 0", "20000, 0.7, 0.3", "1000, 0, 0.1"})
    void fastParticlesNeverLeaveAClosedRingOfLandscape(float speed, float elasticity, float angle) {
        World world = new World();
        Landscape land = ring(world, 24, 200f, angle);
        ParticleEmitter e = ParticleScenes.spray(2000, 1000f, 2f, speed, speed);
        e.setElasticity(elasticity);
        world.addParticleEmitter(e);
        for (int t = 0; t < 400; t++) {
            world.tick();
            assertEnclosed(land, e, t);
        }
        assertEquals(2000, e.getParticleCount());
    }

    /**
     * Crates and balls tumbling in a landscape box and settling on its floor, pressed a little into
     * it by the solver: the particles squeezed between a body and the floor stay inside.
     */
    @Test
    void particlesStayInALandscapeBoxFullOfTumblingBodies() {
        World world = new World();
        float h = 200f;
        Landscape land = world.getLandscape();
        land.addSegment(-h, -h, h, -h);
        land.addSegment(h, -h, h, h);
        land.addSegment(h, h, -h, h);
        land.addSegment(-h, h, -h, -h);
        ParticleScenes.cratesAndBalls(world, 24, -170f, 15f, 150f);
        ParticleEmitter e = ParticleScenes.spray(3000, 3000f, 1000f, 600f, 600f);
        e.setEmitSegment(-60f, -150f, 60f, -150f);
        e.setElasticity(0.8f);
        world.addParticleEmitter(e);
        for (int t = 0; t < 400; t++) {
            world.tick();
            assertEnclosed(land, e, t);
        }
    }

    /**
     * A ball sunk 0.016 px into a landscape wall (within the slop, so it stays) and a particle
     * crawling down the wall one float step from it, into the ball: the ball puts it on its surface,
     * and the point where the particle met the ball rounds onto the wall's line, from which a jump
     * does not count as crossing it. The jump is also tested from the particle's start, so it stays
     * inside; without that, some of these particles ended one skin (1/128 px) beyond the wall.
     */
    @Test
    void aParticleThatABodyPushesAlongAWallStaysInside() {
        for (int k = 0; k < 60; k++) {
            for (float vx : new float[] {0.0007f, 0.0009f, 0.0011f, 0.0013f}) {
                World world = new World();
                world.setTicksPerSecond(60);
                world.setGravity(0f, 0f);
                world.getLandscape().addSegment(200f, -200f, 200f, 200f);
                world.addBody(new Body(190.016f, 190.05f, Shape.createCircle(10f), true));
                float y = 189.38f + 0.002f * k;
                ParticleEmitter e = ParticleScenes.one(world, Math.nextDown(200f), y, vx, 5f);
                world.tick();
                assertTrue(e.getX(0) < 200f, "from y " + y + " at " + vx + " px/s: (" + e.getX(0) + ", " + e.getY(0) + ")");
            }
        }
    }

    /**
     * A static block moved down through the landscape floor tick by tick (a teleport: it sweeps
     * nothing) swallows the particles resting there; those pushed out through its bottom face stop
     * at the floor instead of crossing it.
     */
    @Test
    void aParticlePushedOutOfABodyNeverCrossesTheLandscape() {
        World world = new World();
        world.getLandscape().addSegment(-300f, 150f, 300f, 150f);
        Body block = new Body(0f, 100f, Shape.createRectangle(60f, 40f), false);
        world.addBody(block);
        ParticleEmitter e = new ParticleEmitter(200);
        e.setCreationRate(0f, 0f);
        e.setLifetime(100f, 0f);
        e.setSpeed(0f, 0f);
        e.setEmitSegment(-25f, 149f, 25f, 149f);
        e.setElasticity(0.3f);
        world.addParticleEmitter(e);
        e.emit(200);
        for (int t = 0; t < 80; t++) {
            block.translate(0f, 1.5f);
            world.tick();
            for (int i = 0; i < e.getParticleCount(); i++) {
                assertTrue(e.getY(i) < 150f, "tick " + t + ": " + e.getY(i));
            }
        }
        assertTrue(block.getY() - 20f > 150f + 30f, "the block went through: " + block.getY());
    }

    @Test
    void aPathThroughAJointOfTwoSegmentsIsStopped() {
        World world = new World();
        world.setGravity(0f, 0f);
        // A V: two segments meeting at (0, 0); the particle flies straight at the joint.
        world.getLandscape().addSegment(-100f, -100f, 0f, 0f);
        world.getLandscape().addSegment(0f, 0f, 100f, -100f);
        ParticleEmitter e = ParticleScenes.one(world, 0f, -50f, 0f, 700f);
        ParticleScenes.run(world, 10);
        assertTrue(e.getY(0) < 0f, "stopped above the joint: " + e.getY(0));
    }
}
