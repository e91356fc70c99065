/**
 * Bodies, the world and its tick, contacts and the soft-step contact solver.
 *
 * <p>A contact is born in {@code ContactManager} when the broadphase reports a new pair, updated
 * there by the narrowphase each tick, solved in {@code ContactSolver} on flat arrays prepared from
 * {@code SolverBodies}, and forgotten when the pair's bounding boxes separate.
 */
package org.emini.dynamics;
