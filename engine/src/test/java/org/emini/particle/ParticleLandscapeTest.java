package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.dynamics.World;
import org.emini.math.EMath;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Particles bounce off fixed line segments (the landscape) from either side, and a closed chain of
 * segments holds fast particles for good, joints included.
 */
class ParticleLandscapeTest {
    /** Segments in flat arrays, standing in for the world's landscape. */
    static final class Segments implements SegmentSource {
        private final float[] xy;

        Segments(float... xy) {
            this.xy = xy;
        }

        /** A closed regular polygon of n segments around the origin, radius r, first corner at angle a. */
        static Segments ring(int n, float r, float a) {
            float[] xy = new float[4 * n];
            for (int i = 0; i < n; i++) {
                float a0 = a + EMath.TWO_PI * i / n;
                float a1 = a + EMath.TWO_PI * (i + 1) / n;
                xy[4 * i] = r * EMath.cos(a0);
                xy[4 * i + 1] = r * EMath.sin(a0);
                xy[4 * i + 2] = r * EMath.cos(a1);
                xy[4 * i + 3] = r * EMath.sin(a1);
            }
            return new Segments(xy);
        }

        @Override
        public int getSegmentCount() {
            return xy.length / 4;
        }

        @Override
        public float getStartX(int i) {
            return xy[4 * i];
        }

        @Override
        public float getStartY(int i) {
            return xy[4 * i + 1];
        }

        @Override
        public float getEndX(int i) {
            return xy[4 * i + 2];
        }

        @Override
        public float getEndY(int i) {
            return xy[4 * i + 3];
        }

        /** Whether a point is inside the closed convex ring, on the inner side of every segment. */
        boolean encloses(float x, float y) {
            for (int i = 0; i < getSegmentCount(); i++) {
                float ex = getEndX(i) - getStartX(i);
                float ey = getEndY(i) - getStartY(i);
                if (ex * (y - getStartY(i)) - ey * (x - getStartX(i)) < 0f) {
                    return false;
                }
            }
            return true;
        }
    }

    private static ParticleSystem systemOf(SegmentSource segments) {
        ParticleSystem system = new ParticleSystem();
        system.segments = segments;
        return system;
    }

    private static void step(ParticleSystem system, World world, int ticks) {
        for (int t = 0; t < ticks; t++) {
            world.tick();
            system.step(world, world.getTimestep());
        }
    }

    @ParameterizedTest
    @CsvSource({"0, 300, 0.5", "0, -300, 0.5", "0.4, 250, 1", "-1.2, 250, 0"})
    void aSegmentReflectsTheNormalVelocityFromEitherSide(float tilt, float speed, float elasticity) {
        World world = new World();
        world.setGravity(0f, 0f);
        float c = EMath.cos(tilt);
        float s = EMath.sin(tilt);
        // A segment through the origin along (c, s); the particle comes along its normal (−s, c), offset along it.
        ParticleSystem system = systemOf(new Segments(-500f * c, -500f * s, 500f * c, 500f * s));
        ParticleEmitter e = new ParticleEmitter(1);
        e.setCreationRate(0f, 0f);
        e.setLifetime(100f, 0f);
        float start = -Math.signum(speed) * 100f;
        e.setEmitPoint(-s * start + 30f * c, c * start + 30f * s);
        e.setSpeed(Math.abs(speed), 0f);
        e.setAngle(EMath.atan2(c * Math.signum(speed), -s * Math.signum(speed)), 0f);
        e.setElasticity(elasticity);
        system.addEmitter(e);
        e.emit(1);
        step(system, world, 20);
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
    void fastParticlesNeverLeaveAClosedRingOfSegments(float speed, float elasticity, float angle) {
        World world = new World();
        Segments ring = Segments.ring(24, 200f, angle);
        ParticleSystem system = systemOf(ring);
        ParticleEmitter e = ParticleScenes.spray(2000, 1000f, 2f, speed, speed);
        e.setElasticity(elasticity);
        system.addEmitter(e);
        for (int t = 0; t < 400; t++) {
            world.tick();
            system.step(world, world.getTimestep());
            for (int i = 0; i < e.getParticleCount(); i++) {
                assertTrue(ring.encloses(e.getX(i), e.getY(i)), "tick " + t + ": (" + e.getX(i) + ", " + e.getY(i) + ")");
            }
        }
        assertEquals(2000, e.getParticleCount());
    }

    /**
     * Crates resting on a static slab whose top is the ring's bottom segment press into it; the
     * particles squeezed between a crate and the floor are moved onto the crate but never across
     * the segment.
     */
    @Test
    void aParticlePushedOutOfABodyNeverCrossesTheLandscape() {
        World world = new World();
        float h = 150f;
        Segments box = new Segments(-h, -h, h, -h, h, -h, h, h, h, h, -h, h, -h, h, -h, -h);
        world.addBody(new Body(0f, h + 20f, Shape.createRectangle(2f * h + 100f, 40f), false));
        Shape crate = Shape.createRectangle(30f, 20f);
        for (int i = 0; i < 8; i++) {
            world.addBody(new Body(-120f + 34f * i, h - 10f - 25f * (i % 2), crate, true));
        }
        ParticleSystem system = systemOf(box);
        ParticleEmitter e = ParticleScenes.spray(2000, 2000f, 100f, 600f, 600f);
        e.setEmitPoint(0f, -100f);
        e.setElasticity(0.5f);
        system.addEmitter(e);
        for (int t = 0; t < 300; t++) {
            world.tick();
            system.step(world, world.getTimestep());
            for (int i = 0; i < e.getParticleCount(); i++) {
                assertTrue(box.encloses(e.getX(i), e.getY(i)), "tick " + t + ": (" + e.getX(i) + ", " + e.getY(i) + ")");
            }
        }
    }

    /**
     * A body sinking through the landscape floor (bodies do not see these stand-in segments) sweeps
     * over the particles resting on it: they are moved with its face, but never across the floor.
     */
    @Test
    void aBodySinkingThroughTheFloorDoesNotDragParticlesThrough() {
        World world = new World();
        ParticleSystem system = systemOf(new Segments(-300f, 150f, 300f, 150f));
        Body crate = new Body(0f, 100f, Shape.createRectangle(60f, 40f), true);
        crate.setGravityAffected(false);
        crate.setVelocity(0f, 30f);
        world.addBody(crate);
        ParticleEmitter e = new ParticleEmitter(200);
        e.setCreationRate(0f, 0f);
        e.setLifetime(100f, 0f);
        e.setSpeed(0f, 0f);
        e.setEmitSegment(-25f, 149f, 25f, 149f);
        e.setElasticity(0.3f);
        system.addEmitter(e);
        e.emit(200);
        for (int t = 0; t < 80; t++) {
            world.tick();
            system.step(world, world.getTimestep());
            for (int i = 0; i < e.getParticleCount(); i++) {
                assertTrue(e.getY(i) < 150f, "tick " + t + ": " + e.getY(i));
            }
        }
        assertTrue(crate.getY() - 20f > 150f + 30f, "the crate went through: " + crate.getY());
    }

    @Test
    void aPathThroughAJointOfTwoSegmentsIsStopped() {
        World world = new World();
        world.setGravity(0f, 0f);
        // A V: two segments meeting at (0, 0); the particle flies straight at the joint.
        ParticleSystem system = systemOf(new Segments(-100f, -100f, 0f, 0f, 0f, 0f, 100f, -100f));
        ParticleEmitter e = ParticleScenes.one(world, 0f, -50f, 0f, 0f);
        world.removeParticleEmitter(e);
        e.setSpeed(700f, 0f);
        e.setAngle(EMath.PI / 2f, 0f);
        e.clear();
        e.emit(1);
        system.addEmitter(e);
        step(system, world, 10);
        assertTrue(e.getY(0) < 0f, "stopped above the joint: " + e.getY(0));
    }
}
