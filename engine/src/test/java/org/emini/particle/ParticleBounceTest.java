package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.math.EMath;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A particle that meets a body keeps the tangential part of its velocity and leaves with the
 * normal part reflected and scaled by the emitter's elasticity, relative to the surface.
 */
class ParticleBounceTest {
    /** One particle at (x, y) moving at (vx, vy); returns its emitter. */
    private static ParticleEmitter launch(World world, float x, float y, float vx, float vy, float elasticity) {
        ParticleEmitter e = ParticleScenes.one(world, x, y, vx, vy);
        e.setElasticity(elasticity);
        return e;
    }

    @ParameterizedTest
    @ValueSource(floats = {0f, 0.3f, 0.7f, 1f})
    void normalVelocityIsReflectedAndScaledByElasticityTangentialKept(float elasticity) {
        World world = new World();
        world.setGravity(0f, 0f);
        // A wall whose left face is x = 100.
        world.addBody(new Body(110f, 0f, Shape.createRectangle(20f, 400f), false));
        ParticleEmitter e = launch(world, 0f, 0f, 300f, 40f, elasticity);
        for (int t = 0; t < 8; t++) {
            world.tick();
        }
        // Reached the wall at t = 1/3 s, in the seventh tick.
        assertEquals(-300f * elasticity, e.getVelocityX(0), 1e-3);
        assertEquals(40f, e.getVelocityY(0), 1e-4);
        assertTrue(e.getX(0) < 100f);
        // It went on from the wall for the rest of the seventh tick and the eighth: 8 × 0.05 − 1/3 s.
        float after = 8 * 0.05f - 1f / 3f;
        assertEquals(100f - ParticleCollider.SKIN - 300f * elasticity * after, e.getX(0), 2e-3);
        assertEquals(40f * 8 * 0.05f, e.getY(0), 2e-3);
    }

    /** Under gravity the rebound reaches e² times the drop height (v = e·√(2gH), height v²/2g). */
    @ParameterizedTest
    @ValueSource(floats = {0.4f, 0.6f, 0.9f, 1f})
    void reboundHeightIsElasticitySquaredTimesDropHeight(float elasticity) {
        World world = new World();
        world.addBody(new Body(0f, 50f, Shape.createRectangle(400f, 100f), false));
        ParticleEmitter e = launch(world, 0f, -200f, 0f, 0f, elasticity);
        float top = 0f;
        boolean bounced = false;
        for (int t = 0; t < 400; t++) {
            world.tick();
            bounced |= e.getVelocityY(0) < 0f;
            if (bounced) {
                top = Math.min(top, e.getY(0));
                if (e.getVelocityY(0) > 0f && e.getY(0) > 0.5f * top) {
                    break;
                }
            }
        }
        // Sampled at ticks, the apex is seen within ½·g·(dt/2)² = 0.03 px.
        assertEquals(-200f * elasticity * elasticity, top, 0.1f + 0.002f * 200f);
    }

    @Test
    void speedIsKeptAndTheAngleMirroredAboutTheRadiusOfACircle() {
        World world = new World();
        world.setGravity(0f, 0f);
        world.addBody(new Body(200f, 0f, Shape.createCircle(50f), false));
        // Aimed 30 px off the centre line: it meets the rim where the normal makes asin(0.6) with −x.
        ParticleEmitter e = launch(world, 0f, -30f, 400f, 0f, 1f);
        ParticleScenes.run(world, 12);
        double sinA = 0.6;
        double cosA = 0.8;
        // Incoming (1, 0) mirrored about the normal (−cos, −sin): (1 − 2cos², −2cos·sin).
        assertEquals(400.0 * (1 - 2 * cosA * cosA), e.getVelocityX(0), 0.05);
        assertEquals(400.0 * (-2 * cosA * sinA), e.getVelocityY(0), 0.05);
        float dx = e.getX(0) - 200f;
        float dy = e.getY(0);
        assertTrue(dx * dx + dy * dy > 50f * 50f, "outside the circle");
    }

    @Test
    void particlesComeToRestOnAFloorWithoutJitter() {
        World world = new World();
        world.addBody(new Body(0f, 50f, Shape.createRectangle(400f, 100f), false));
        ParticleEmitter e = launch(world, 0f, -100f, 0f, 0f, 0.5f);
        ParticleScenes.run(world, 200);
        for (int t = 0; t < 40; t++) {
            world.tick();
            assertEquals(-ParticleCollider.SKIN, e.getY(0), 1e-3, "lies on the floor");
            assertEquals(0f, e.getVelocityY(0), 100f * world.getTimestep(), "at most one tick of gravity");
        }
    }

    @Test
    void aParticleSlidesAlongAFloorWithItsTangentialSpeed() {
        World world = new World();
        world.addBody(new Body(0f, 50f, Shape.createRectangle(4000f, 100f), false));
        ParticleEmitter e = launch(world, 0f, -ParticleCollider.SKIN, 50f, 0f, 0f);
        ParticleScenes.run(world, 40);
        assertEquals(100f, e.getX(0), 0.01f, "50 px/s for 2 s");
        assertEquals(-ParticleCollider.SKIN, e.getY(0), 1e-3);
    }

    @Test
    void aBodyMovingIntoAParticleThrowsItAtTwiceItsSpeed() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body paddle = new Body(-100f, 0f, Shape.createRectangle(20f, 200f), true);
        paddle.setVelocity(200f, 0f);
        world.addBody(paddle);
        ParticleEmitter e = launch(world, 0f, 0f, 0f, 0f, 1f);
        ParticleScenes.run(world, 12);
        // Elastic bounce off a (much heavier) wall moving at u: the particle leaves at 2u.
        assertEquals(400f, e.getVelocityX(0), 1e-2);
        assertEquals(0f, e.getVelocityY(0), 1e-4);
        assertTrue(e.getX(0) > paddle.getX() + 10f, "in front of the paddle");
        assertEquals(200f, paddle.getVelocityX(), 1e-3, "particles push nothing");
    }

    /**
     * A bar turning at ω about its centre strikes a resting particle at distance d along its axis:
     * the face moves at ω·d along its normal, and an elastic particle leaves at 2·ω·d along it.
     */
    @Test
    void aTurningBarThrowsAParticleAtTwiceItsFaceSpeed() {
        World world = new World();
        world.setGravity(0f, 0f);
        Body bar = new Body(0f, 0f, Shape.createRectangle(100f, 10f), true);
        bar.setAngularVelocity(4f);
        world.addBody(bar);
        ParticleEmitter e = launch(world, 40f, 20f, 0f, 0f, 1f);
        ParticleScenes.run(world, 3);
        double along = Math.sqrt(40.0 * 40.0 + 20.0 * 20.0 - 5.0 * 5.0);
        float vx = e.getVelocityX(0);
        float vy = e.getVelocityY(0);
        assertEquals(2.0 * 4.0 * along, Math.sqrt(vx * vx + vy * vy), 0.03 * 2.0 * 4.0 * along);
        // Along the bar's normal (−sin θ, cos θ) at the hit, θ = atan(20/40) − asin(5/d).
        double theta = Math.atan2(20.0, 40.0) - Math.asin(5.0 / Math.sqrt(40.0 * 40.0 + 20.0 * 20.0));
        assertEquals(Math.atan2(Math.cos(theta), -Math.sin(theta)), Math.atan2(vy, vx), 0.05);
        assertTrue(bar.toLocalY(e.getX(0), e.getY(0)) > 5f, "ahead of the bar's face");
    }
}
