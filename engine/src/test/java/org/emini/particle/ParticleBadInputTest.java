package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.shape.Shape;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/** Bad settings are refused at the call that introduces them, with a message naming it. */
class ParticleBadInputTest {
    private static void refused(String expectedInMessage, Executable call) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, call);
        assertTrue(e.getMessage().contains(expectedInMessage), e.getMessage());
    }

    @Test
    void settingsRefuseNonFiniteAndOutOfRangeValues() {
        ParticleEmitter e = new ParticleEmitter(10);
        refused("ParticleEmitter(maxParticles, body): maxParticles must be in 1..1048576, was 0", () -> new ParticleEmitter(0));
        refused("ParticleEmitter.setMaxParticles: maxParticles must be in 1..1048576, was -3", () -> e.setMaxParticles(-3));
        refused("ParticleEmitter.setCreationRate: rate must be in [0.0, 1000000.0], was -1.0", () -> e.setCreationRate(-1f, 0f));
        refused("ParticleEmitter.setCreationRate: deviation must be in [0.0, 1000000.0], was NaN", () -> e.setCreationRate(1f, Float.NaN));
        refused("ParticleEmitter.setLifetime: seconds must be > 0, was 0.0", () -> e.setLifetime(0f, 0f));
        refused("ParticleEmitter.setLifetime: deviation must be in [0.0, 1000000.0], was -1.0", () -> e.setLifetime(1f, -1f));
        refused("ParticleEmitter.setSpeed: speed must be in [-1000000.0, 1000000.0], was Infinity", () -> e.setSpeed(Float.POSITIVE_INFINITY, 0f));
        refused("ParticleEmitter.setAngle: radians", () -> e.setAngle(Float.NaN, 0f));
        refused("ParticleEmitter.setEmitSegment: y2", () -> e.setEmitSegment(0f, 0f, 0f, Float.NaN));
        refused("ParticleEmitter.setElasticity: elasticity must be in [0, 1], was 1.5", () -> e.setElasticity(1.5f));
        refused("ParticleEmitter.setDamping: damping must be in [0, 1], was -0.1", () -> e.setDamping(-0.1f));
        refused("ParticleEmitter.setGravityFactor: factor", () -> e.setGravityFactor(Float.NaN));
        refused("ParticleEmitter.emit: particles must be >= 0, was -1", () -> e.emit(-1));
        refused("ParticleEmitter.copyPositions: out must hold", () -> e.copyPositions(null));
    }

    /** Values that used to be taken and turned into NaN or infinite particles a few ticks later. */
    @Test
    void valuesBeyondTheSupportedRangesAreRefusedNamingTheCallAndTheValue() {
        ParticleEmitter e = new ParticleEmitter(10);
        float huge = 3.4e38f;
        refused("ParticleEmitter.setEmitSegment: x1 must be in [-1.0E7, 1.0E7], was 3.4E38", () -> e.setEmitPoint(huge, 0f));
        refused("ParticleEmitter.setEmitSegment: y1 must be in [-1.0E7, 1.0E7], was NaN", () -> e.setEmitPoint(0f, Float.NaN));
        refused("ParticleEmitter.setEmitSegment: x2 must be in [-1.0E7, 1.0E7], was -3.4E38", () -> e.setEmitSegment(0f, 0f, -huge, 0f));
        refused("ParticleEmitter.setGravityFactor: factor must be in [-10000.0, 10000.0], was 3.4E38", () -> e.setGravityFactor(huge));
        refused("ParticleEmitter.setSpeed: speed must be in [-1000000.0, 1000000.0], was -3.4E38", () -> e.setSpeed(-huge, 0f));
        refused("ParticleEmitter.setSpeed: deviation must be in [0.0, 1000000.0], was 3.4E38", () -> e.setSpeed(0f, huge));
        refused("ParticleEmitter.setCreationRate: rate must be in [0.0, 1000000.0], was 3.4E38", () -> e.setCreationRate(huge, 0f));
        refused("ParticleEmitter.setLifetime: seconds must be in [0.0, 1000000.0], was 3.4E38", () -> e.setLifetime(huge, 0f));
        refused("ParticleEmitter.setLifetime: deviation must be in [0.0, 1000000.0], was 3.4E38", () -> e.setLifetime(1f, huge));
        refused("ParticleEmitter.setAngle: radians must be in [-10000.0, 10000.0], was 3.4E38", () -> e.setAngle(huge, 0f));
        refused("ParticleEmitter.setAngle: deviation must be in [0.0, 10000.0], was 3.4E38", () -> e.setAngle(0f, huge));
        refused("ParticleEmitter(maxParticles, body): maxParticles must be in 1..1048576, was 100000000",
            () -> new ParticleEmitter(100_000_000));
        refused("ParticleEmitter.setMaxParticles: maxParticles must be in 1..1048576, was 2147483647",
            () -> e.setMaxParticles(Integer.MAX_VALUE));
        // The limits themselves are taken, and make finite particles.
        e.setEmitSegment(-ParticleEmitter.MAX_COORDINATE, 0f, ParticleEmitter.MAX_COORDINATE, 0f);
        e.setSpeed(ParticleEmitter.MAX_SPEED, ParticleEmitter.MAX_SPEED);
        e.setGravityFactor(-ParticleEmitter.MAX_GRAVITY_FACTOR);
        e.setAngle(ParticleEmitter.MAX_ANGLE, ParticleEmitter.MAX_ANGLE);
        e.setLifetime(ParticleEmitter.MAX_LIFETIME, ParticleEmitter.MAX_LIFETIME);
        e.setCreationRate(ParticleEmitter.MAX_RATE, ParticleEmitter.MAX_RATE);
        World world = new World();
        world.addParticleEmitter(e);
        for (int t = 0; t < 100; t++) {
            world.tick();
        }
        assertTrue(e.getParticleCount() == 10);
        for (int i = 0; i < e.getParticleCount(); i++) {
            float sum = e.getX(i) + e.getY(i) + e.getVelocityX(i) + e.getVelocityY(i);
            assertTrue(sum - sum == 0f, "particle " + i + " at (" + e.getX(i) + ", " + e.getY(i) + ")");
        }
    }

    @Test
    void particleIndicesAreChecked() {
        ParticleEmitter e = new ParticleEmitter(10);
        e.emit(2);
        IndexOutOfBoundsException x = assertThrows(IndexOutOfBoundsException.class, () -> e.getX(2));
        assertTrue(x.getMessage().contains("ParticleEmitter.getX: index 2 of 2"), x.getMessage());
        assertThrows(IndexOutOfBoundsException.class, () -> e.getAge(-1));
    }

    @Test
    void anEmitterBelongsToOneWorldAndItsBodyToThatWorld() {
        World world = new World();
        World other = new World();
        ParticleEmitter e = new ParticleEmitter(10);
        world.addParticleEmitter(e);
        refused("World.addParticleEmitter: ParticleEmitter[0 of 10 particles, fixed] already belongs to a world",
            () -> other.addParticleEmitter(e));
        refused("World.addParticleEmitter: emitter must not be null", () -> world.addParticleEmitter(null));
        Body body = new Body(0f, 0f, Shape.createCircle(3f), true);
        refused("World.addParticleEmitter: the emitter's body Body#-1", () -> world.addParticleEmitter(new ParticleEmitter(5, body)));
        assertThrows(IndexOutOfBoundsException.class, () -> world.getParticleEmitter(1));
        refused("ParticleSystem.step: dt must be finite and > 0, was 0.0", () -> new ParticleSystem().step(world, 0f));
    }
}
