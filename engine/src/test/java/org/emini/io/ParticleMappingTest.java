package org.emini.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.world.World;
import org.emini.particle.ParticleEmitter;
import org.junit.jupiter.api.Test;

/** Particle emitters of a world file in the engine. */
class ParticleMappingTest {
    /** The designer's "new emitter": rate 20/s, lifetime 2 s, speed 10 px/s, elasticity 1, gravity 1. */
    private static PhyParticleEmitter designerDefault() {
        PhyParticleEmitter p = new PhyParticleEmitter();
        p.setMaxParticles(100);
        p.setRateRaw(20 * 4096);
        p.setLifetimeRaw(2 * 4096);
        p.setSpeedRaw(10 * 4096);
        p.setElasticityRaw(4096);
        p.setGravityFactorRaw(4096);
        return p;
    }

    @Test
    void anEmitterKeepsEveryStoredSetting() {
        PhyWorld doc = new PhyWorld();
        doc.getShapes().add(new PhyShape(PhyVector.of(0, 10)));
        doc.getBodies().add(new PhyBody());
        PhyParticleEmitter p = designerDefault();
        p.setBody(0);
        p.setAxesFixedByte(1);
        p.setPosition1(PhyVector.of(0, -12));
        p.setPosition2(PhyVector.of(4, -12));
        p.setEmitAngleRaw(-PhyFixed.PI_2FX / 2);
        p.setEmitAngleSpreadRaw(PhyFixed.PI_2FX / 6);
        p.setSpeedSpreadRaw(2 * 4096);
        p.setRateSpreadRaw(4096);
        p.setLifetimeSpreadRaw(2048);
        p.setDampingRaw(410);
        p.setGravityFactorRaw(2048);
        doc.getParticleEmitters().add(p);
        BuildResult r = new WorldBuilder().build(doc);
        ParticleEmitter e = r.getParticleEmitter(0);
        assertSame(r.getBody(0), e.getBody());
        assertSame(e, r.getWorld().getParticleEmitter(0));
        assertEquals(100, e.getMaxParticles());
        assertEquals(20f, e.getCreationRate());
        assertEquals(1f, e.getCreationRateDeviation());
        assertEquals(2f, e.getLifetime());
        assertEquals(0.5f, e.getLifetimeDeviation());
        assertEquals(10f, e.getSpeed());
        assertEquals(2f, e.getSpeedDeviation());
        assertEquals(PhyFixed.fx2(-PhyFixed.PI_2FX / 2), e.getAngle(), "up the screen, as stored: angles keep their sign");
        assertEquals(PhyFixed.fx2(PhyFixed.PI_2FX / 6), e.getAngleDeviation());
        assertEquals(-12f, e.getEmitY1());
        assertEquals(4f, e.getEmitX2());
        assertTrue(e.isAxesFixed());
        assertEquals(1f, e.getElasticity());
        assertEquals(0.5f, e.getGravityFactor());
        assertEquals(410 / 4096f, e.getDamping());
    }

    @Test
    void aFixedEmitterFillsAtItsRate() {
        PhyWorld doc = new PhyWorld();
        PhyWorldSettings s = new PhyWorldSettings();
        s.setGravity(PhyVector.ZERO);
        doc.setSettings(s);
        doc.getParticleEmitters().add(designerDefault());
        World world = new WorldBuilder().build(doc).getWorld();
        for (int t = 0; t < 20; t++) {
            world.tick();
        }
        // 20 particles per second for one second, none dead yet (lifetime 2 s).
        assertEquals(20, world.getParticleEmitter(0).getParticleCount(), 1);
    }

    @Test
    void anAbsurdCapacityIsListedInsteadOfAllocated() {
        PhyWorld doc = new PhyWorld();
        PhyParticleEmitter huge = designerDefault();
        huge.setMaxParticles(Integer.MAX_VALUE);
        doc.getParticleEmitters().add(huge);
        PhyParticleEmitter none = designerDefault();
        none.setMaxParticles(0);
        doc.getParticleEmitters().add(none);
        PhyParticleEmitter orphan = designerDefault();
        orphan.setBody(3);
        doc.getParticleEmitters().add(orphan);
        BuildResult r = new WorldBuilder().build(doc);
        assertNull(r.getParticleEmitter(0));
        assertEquals("particle emitter 0: capacity 2147483647 is above the builder's particle limit 65536",
                r.getUnsupported().get(0).toString());
        assertEquals(UnsupportedElement.Kind.PARTICLE_EMITTER, r.getUnsupported().get(1).getKind());
        assertEquals("particle emitter 2: its body 3 does not exist", r.getUnsupported().get(2).toString());
        assertEquals(0, r.getWorld().getParticleEmitterCount());
        assertTrue(new WorldBuilder().setParticleLimit(200).build(doc).getUnsupported().get(0).getReason()
                .contains("limit 200"));
        assertThrows(IllegalArgumentException.class, () -> new WorldBuilder().setParticleLimit(0));
    }
}
