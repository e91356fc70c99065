package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.math.EMath;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/**
 * An emitter on a body emits from the body point its emit point names, rotated with the body
 * (unless the axes are fixed), in the emit direction turned by the body's angle, and adds the
 * velocity of that point (v + ω × r) to the emit velocity.
 */
class AttachedEmitterTest {
    /** A weightless world with a body moving at (30, −20) px/s and turning at 2 rad/s. */
    private static World movingBody(Body[] out) {
        World world = new World();
        world.setGravity(0f, 0f);
        Body b = new Body(100f, 50f, Shape.createRectangle(20f, 10f), true);
        b.setAngle(0.3f);
        b.setVelocity(30f, -20f);
        b.setAngularVelocity(2f);
        b.setInteracting(false);
        world.addBody(b);
        out[0] = b;
        return world;
    }

    /** Emits one particle at each of 25 ticks, with speed 40 px/s at angle 0.5 from (15, 5). */
    private static void burstEachTick(World world, Body b, boolean axesFixed, Runnable check) {
        ParticleEmitter e = new ParticleEmitter(100, b);
        e.setCreationRate(0f, 0f);
        e.setEmitPoint(15f, 5f);
        e.setSpeed(40f, 0f);
        e.setAngle(0.5f, 0f);
        e.setAxesFixed(axesFixed);
        world.addParticleEmitter(e);
        for (int t = 0; t < 25; t++) {
            world.tick();
            e.clear();
            e.emit(1);
            check.run();
        }
    }

    @Test
    void aParticleStartsAtTheRotatedEmitPointWithThatPointsVelocity() {
        Body[] body = new Body[1];
        World world = movingBody(body);
        Body b = body[0];
        burstEachTick(world, b, false, () -> {
            ParticleEmitter e = world.getParticleEmitter(0);
            float px = b.toWorldX(15f, 5f);
            float py = b.toWorldY(15f, 5f);
            assertEquals(px, e.getX(0), 1e-4f);
            assertEquals(py, e.getY(0), 1e-4f);
            float a = b.getAngle() + 0.5f;
            assertEquals(b.getPointVelocityX(px, py) + 40f * EMath.cos(a), e.getVelocityX(0), 1e-3f);
            assertEquals(b.getPointVelocityY(px, py) + 40f * EMath.sin(a), e.getVelocityY(0), 1e-3f);
        });
        assertTrue(Math.abs(b.getAngle() - 0.3f) > 2f, "the body turned: " + b.getAngle());
    }

    @Test
    void withFixedAxesTheEmitPointIsAWorldOffsetAndTheDirectionIgnoresTheBody() {
        Body[] body = new Body[1];
        World world = movingBody(body);
        Body b = body[0];
        burstEachTick(world, b, true, () -> {
            ParticleEmitter e = world.getParticleEmitter(0);
            assertEquals(b.getX() + 15f, e.getX(0), 1e-4f);
            assertEquals(b.getY() + 5f, e.getY(0), 1e-4f);
            assertEquals(b.getVelocityX() + 40f * EMath.cos(0.5f), e.getVelocityX(0), 1e-3f);
            assertEquals(b.getVelocityY() + 40f * EMath.sin(0.5f), e.getVelocityY(0), 1e-3f);
        });
    }

    /**
     * Steady emission from a moving, turning body: a particle born a seconds before the end of the
     * tick left the emit point then and has moved with its own velocity since, so with emit speed
     * 0 it lies, to first order in a, where the emit point is now.
     */
    @Test
    void particlesBornDuringATickLeaveFromTheMovingEmitPoint() {
        Body[] body = new Body[1];
        World world = movingBody(body);
        Body b = body[0];
        ParticleEmitter e = new ParticleEmitter(10_000, b);
        e.setCreationRate(400f, 0f);
        e.setSpeed(0f, 0f);
        e.setEmitPoint(15f, 5f);
        world.addParticleEmitter(e);
        for (int t = 0; t < 30; t++) {
            int before = e.getParticleCount();
            world.tick();
            float px = b.toWorldX(15f, 5f);
            float py = b.toWorldY(15f, 5f);
            assertEquals(before + 20, e.getParticleCount());
            for (int i = before; i < e.getParticleCount(); i++) {
                assertEquals(px, e.getX(i), 1e-4f);
                assertEquals(py, e.getY(i), 1e-4f);
                assertEquals(b.getPointVelocityX(px, py), e.getVelocityX(i), 1e-3f);
                assertEquals(b.getPointVelocityY(px, py), e.getVelocityY(i), 1e-3f);
            }
        }
        // Earlier particles kept the velocity they left with: each lies on its own straight line.
        for (int i = 0; i < e.getParticleCount(); i++) {
            assertTrue(e.getAge(i) <= 30 * world.getTimestep() + 1e-5f);
        }
    }

    @Test
    void particlesLeaveFromUniformPointsOfTheEmitSegment() {
        Body[] body = new Body[1];
        World world = movingBody(body);
        Body b = body[0];
        ParticleEmitter e = new ParticleEmitter(4000, b);
        e.setCreationRate(0f, 0f);
        e.setSpeed(0f, 0f);
        e.setEmitSegment(-10f, 5f, 30f, -15f);
        world.addParticleEmitter(e);
        ParticleScenes.run(world, 5);
        e.emit(4000);
        double sum = 0;
        float lo = 1f;
        float hi = 0f;
        for (int i = 0; i < 4000; i++) {
            float lx = b.toLocalX(e.getX(i), e.getY(i));
            float ly = b.toLocalY(e.getX(i), e.getY(i));
            float u = (lx + 10f) / 40f;
            assertEquals(5f - 20f * u, ly, 1e-3f, "on the segment");
            lo = Math.min(lo, u);
            hi = Math.max(hi, u);
            sum += u;
        }
        assertEquals(0.5, sum / 4000, 0.02);
        assertTrue(lo > -1e-4f && lo < 0.01f && hi < 1.0001f && hi > 0.99f, lo + " .. " + hi);
    }

    @Test
    void removingTheBodyRemovesItsEmitters() {
        Body[] body = new Body[1];
        World world = movingBody(body);
        ParticleEmitter onBody = new ParticleEmitter(10, body[0]);
        ParticleEmitter fixed = new ParticleEmitter(10);
        world.addParticleEmitter(onBody);
        world.addParticleEmitter(fixed);
        assertEquals(2, world.getParticleEmitterCount());
        world.removeBody(body[0]);
        assertEquals(1, world.getParticleEmitterCount());
        assertEquals(fixed, world.getParticleEmitter(0));
        assertTrue(world.removeParticleEmitter(fixed));
        assertFalse(world.removeParticleEmitter(fixed));
        // Free again: it may join another world.
        new World().addParticleEmitter(fixed);
    }
}
