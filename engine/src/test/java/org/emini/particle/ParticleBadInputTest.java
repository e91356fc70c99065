package org.emini.particle;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.dynamics.World;
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
        refused("ParticleEmitter(maxParticles, body): maxParticles must be > 0, was 0", () -> new ParticleEmitter(0));
        refused("ParticleEmitter.setMaxParticles: maxParticles must be > 0, was -3", () -> e.setMaxParticles(-3));
        refused("ParticleEmitter.setCreationRate: rate must be >= 0, was -1.0", () -> e.setCreationRate(-1f, 0f));
        refused("ParticleEmitter.setCreationRate: deviation must be a finite number, was NaN", () -> e.setCreationRate(1f, Float.NaN));
        refused("ParticleEmitter.setLifetime: seconds must be > 0, was 0.0", () -> e.setLifetime(0f, 0f));
        refused("ParticleEmitter.setLifetime: deviation must be >= 0", () -> e.setLifetime(1f, -1f));
        refused("ParticleEmitter.setSpeed: speed must be a finite number, was Infinity", () -> e.setSpeed(Float.POSITIVE_INFINITY, 0f));
        refused("ParticleEmitter.setAngle: radians", () -> e.setAngle(Float.NaN, 0f));
        refused("ParticleEmitter.setEmitSegment: y2", () -> e.setEmitSegment(0f, 0f, 0f, Float.NaN));
        refused("ParticleEmitter.setElasticity: elasticity must be in [0, 1], was 1.5", () -> e.setElasticity(1.5f));
        refused("ParticleEmitter.setDamping: damping must be in [0, 1], was -0.1", () -> e.setDamping(-0.1f));
        refused("ParticleEmitter.setGravityFactor: factor", () -> e.setGravityFactor(Float.NaN));
        refused("ParticleEmitter.emit: particles must be >= 0, was -1", () -> e.emit(-1));
        refused("ParticleEmitter.copyPositions: out must hold", () -> e.copyPositions(null));
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
