/**
 * Particles: {@link org.emini.particle.ParticleEmitter}s that emit particles, fixed in the world
 * or carried by a body, and the {@link org.emini.particle.ParticleSystem} that moves them under
 * gravity and bounces them off bodies; particles never touch each other or push anything.
 *
 * <p>Each emitter keeps its particles in a preallocated pool of flat float arrays (dead particles
 * are replaced by the last live one), so a tick allocates nothing; each draws its random numbers
 * from its own seeded generator, so particles are deterministic.
 */
package org.emini.particle;
