package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;

/** The same world with the same seeds gives bit-identical particles; another seed, others. */
class ParticleDeterminismTest {
    /** Falling bodies in a box, a spray with every deviation, and an emitter on a tumbling body. */
    static World scene(long seed) {
        World world = new World();
        ParticleScenes.box(world, 200f, 4f, 0f);
        Shape crate = Shape.createRectangle(24f, 16f);
        Body carrier = null;
        for (int i = 0; i < 12; i++) {
            Body b = new Body(-150f + 27f * i, -100f - 13f * (i % 3), i % 2 == 0 ? crate : Shape.createCircle(9f), true);
            b.setAngle(0.2f * i);
            world.addBody(b);
            carrier = b;
        }
        ParticleEmitter spray = ParticleScenes.spray(10_000, 800f, 3f, 400f, 300f);
        spray.setCreationRate(800f, 400f);
        spray.setLifetime(3f, 2f);
        spray.setEmitSegment(-50f, 50f, 50f, 30f);
        spray.setElasticity(0.7f);
        spray.setDamping(0.01f);
        spray.setSeed(seed);
        world.addParticleEmitter(spray);
        ParticleEmitter exhaust = new ParticleEmitter(2000, carrier);
        exhaust.setEmitPoint(0f, 12f);
        exhaust.setAngle(1.2f, 0.8f);
        exhaust.setSpeed(150f, 60f);
        exhaust.setCreationRate(300f, 100f);
        exhaust.setGravityFactor(-0.3f);
        exhaust.setSeed(seed + 1);
        world.addParticleEmitter(exhaust);
        return world;
    }

    static long hash(World world) {
        long h = 1125899906842597L;
        for (int k = 0; k < world.getParticleEmitterCount(); k++) {
            ParticleEmitter e = world.getParticleEmitter(k);
            h = 31 * h + e.getParticleCount();
            for (int i = 0; i < e.getParticleCount(); i++) {
                h = 31 * h + Float.floatToIntBits(e.getX(i));
                h = 31 * h + Float.floatToIntBits(e.getY(i));
                h = 31 * h + Float.floatToIntBits(e.getVelocityX(i));
                h = 31 * h + Float.floatToIntBits(e.getVelocityY(i));
                h = 31 * h + Float.floatToIntBits(e.getAge(i));
                h = 31 * h + Float.floatToIntBits(e.getParticleLifetime(i));
            }
        }
        return h;
    }

    @Test
    void theSameSeedGivesBitIdenticalParticles() {
        World a = scene(42L);
        World b = scene(42L);
        for (int t = 0; t < 300; t++) {
            a.tick();
            b.tick();
            assertEquals(hash(a), hash(b), "tick " + t);
        }
    }

    @Test
    void anotherSeedGivesOtherParticles() {
        World a = scene(42L);
        World b = scene(43L);
        ParticleScenes.run(a, 20);
        ParticleScenes.run(b, 20);
        assertNotEquals(hash(a), hash(b));
    }

    @Test
    void reseedingRepeatsTheSequence() {
        World world = new World();
        ParticleEmitter e = ParticleScenes.spray(1000, 0f, 5f, 100f, 50f);
        world.addParticleEmitter(e);
        e.setSeed(7L);
        e.emit(100);
        float[] first = new float[200];
        e.copyPositions(first);
        long h = hash(world);
        e.clear();
        e.setSeed(7L);
        e.emit(100);
        assertEquals(h, hash(world));
        assertEquals(7L, e.getSeed());
    }
}
