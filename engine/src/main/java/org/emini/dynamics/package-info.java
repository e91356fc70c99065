/**
 * Bodies, the world and its tick, the landscape, contacts and the soft-step contact solver.
 *
 * <p>A contact is born in {@code ContactManager} when the broadphase reports a new pair, updated
 * there by the narrowphase each tick, solved in {@code ContactSolver} on flat arrays prepared from
 * {@code SolverBodies}, and forgotten when the pair's bounding boxes separate. Landscape contacts
 * (a dynamic body and a {@link org.emini.dynamics.Landscape} segment) live alongside, found through
 * the landscape's own static tree. {@code SimulationArea} picks the bodies a tick simulates.
 */
package org.emini.dynamics;
