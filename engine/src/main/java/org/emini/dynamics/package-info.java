/**
 * Bodies, the world and its tick, the landscape, contacts and the soft-step contact solver.
 *
 * <p>For users: {@link org.emini.dynamics.Body}, {@link org.emini.dynamics.Landscape},
 * {@link org.emini.dynamics.Contact}, {@link org.emini.dynamics.StepData}, the queries' types and
 * {@link org.emini.dynamics.SolverSettings}. {@link org.emini.dynamics.SolverStep} is the solver's
 * state during a tick, for authors of their own {@link org.emini.dynamics.Constraint} only; the
 * solver's other classes are package-private.
 *
 * <p>A contact is born in {@code ContactManager} when the broadphase reports a new pair, updated
 * there by the narrowphase each tick, solved in {@code ContactSolver} on flat arrays prepared from
 * {@code SolverBodies}, and forgotten when the pair's bounding boxes separate. Landscape contacts
 * (a dynamic body and a {@link org.emini.dynamics.Landscape} segment) live alongside, found through
 * the landscape's own static tree. {@code SimulationArea} picks the bodies a tick simulates.
 *
 * <p>The world's queries ({@link org.emini.dynamics.Simulation#rayCast},
 * {@link org.emini.dynamics.Simulation#castShape}, {@link org.emini.dynamics.Simulation#queryPoint},
 * {@link org.emini.dynamics.Simulation#overlapShape} and their kin) live in {@code WorldQuery}: it
 * finds candidates as {@link org.emini.dynamics.Simulation#queryBodies} does ({@code BodyQuery}),
 * tests them exactly, and fills a {@link org.emini.dynamics.CastHit} or calls a
 * {@link org.emini.dynamics.CastCallback}.
 */
package org.emini.dynamics;
