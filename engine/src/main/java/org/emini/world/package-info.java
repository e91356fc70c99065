/**
 * The world applications build and tick: {@link org.emini.world.World} runs the physics of
 * {@link org.emini.dynamics.Simulation} and adds what acts before the solve (external forces) and
 * what reads its result (particles, events). The top of the pipeline: it may use every package
 * below it, and none of them uses it.
 */
package org.emini.world;
