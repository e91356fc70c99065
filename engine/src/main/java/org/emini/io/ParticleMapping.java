package org.emini.io;

import org.emini.dynamics.Body;
import org.emini.particle.ParticleEmitter;

/** Particle emitters of a world file as engine emitters (see phy-mapping.md). */
final class ParticleMapping {
    private ParticleMapping() {
    }

    /**
     * Builds an emitter, or lists it.
     *
     * @param limit the largest capacity built: a file may ask for 2³¹ − 1 particles
     * @return the emitter, or null when it is not built
     */
    static ParticleEmitter build(PhyParticleEmitter p, int index, BuildResult r, int limit) {
        Body body = null;
        if (p.getBody() != PhyWorld.NONE && (body = r.bodyAt(p.getBody())) == null) {
            r.unsupported(UnsupportedElement.Kind.PARTICLE_EMITTER, index,
                    BuildResult.missing("body", p.getBody(), r.getDocument().getBodies().size()));
            return null;
        }
        if (p.getMaxParticles() > limit) {
            r.unsupported(UnsupportedElement.Kind.PARTICLE_EMITTER, index, "capacity " + p.getMaxParticles()
                    + " is above the builder's particle limit " + limit);
            return null;
        }
        try {
            ParticleEmitter e = new ParticleEmitter(p.getMaxParticles(), body);
            e.setEmitSegment(p.getPosition1().getX(), p.getPosition1().getY(), p.getPosition2().getX(),
                    p.getPosition2().getY());
            e.setAngle(p.getEmitAngle(), p.getEmitAngleSpread());
            e.setSpeed(p.getSpeed(), p.getSpeedSpread());
            e.setCreationRate(p.getRate(), p.getRateSpread());
            e.setLifetime(p.getLifetime(), p.getLifetimeSpread());
            e.setAxesFixed(p.isAxesFixed());
            e.setElasticity(WorldBuilder.unit(p.getElasticity(), UnsupportedElement.Kind.PARTICLE_EMITTER, index,
                    "elasticity", r));
            e.setGravityFactor(p.getGravityFactor());
            e.setDamping(WorldBuilder.unit(p.getDamping(), UnsupportedElement.Kind.PARTICLE_EMITTER, index,
                    "damping", r));
            // The original draws from one shared random source; here each emitter has its own seed.
            e.setSeed(ParticleEmitter.DEFAULT_SEED + index);
            return e;
        } catch (IllegalArgumentException x) {
            r.unsupported(UnsupportedElement.Kind.PARTICLE_EMITTER, index, x.getMessage());
            return null;
        }
    }
}
