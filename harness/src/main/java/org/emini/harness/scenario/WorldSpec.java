package org.emini.harness.scenario;

import java.util.Map;

/**
 * World settings with the manual's defaults filled in.
 *
 * @param timestep seconds per tick (default 1/20)
 * @param iterations constraint iterations (default 10)
 * @param dynamicIterations stop iterating once converged (default false)
 * @param gravityX px/s² (default 0)
 * @param gravityY px/s² (default 100, down the screen)
 * @param dampingLateral fraction of linear velocity removed per tick (default 0)
 * @param dampingRotational fraction of angular velocity removed per tick (default 0)
 * @param hasSimulationArea whether the scene limits the simulated x range (not yet in the engine)
 * @param solver engine tunables the scene sets, by SolverSettings name
 * @param sleeping whether bodies may fall asleep, with the tolerances the scene sets (default off)
 */
public record WorldSpec(double timestep, int iterations, boolean dynamicIterations, double gravityX,
                        double gravityY, double dampingLateral, double dampingRotational,
                        boolean hasSimulationArea, Map<String, Double> solver, SleepSpec sleeping) {
    /** The manual's world. */
    public static final WorldSpec DEFAULT = new WorldSpec(1.0 / 20, 10, false, 0, 100, 0, 0, false, Map.of(),
            SleepSpec.OFF);

    /** The same world with another sleeping setting. */
    public WorldSpec withSleeping(SleepSpec newSleeping) {
        return new WorldSpec(timestep, iterations, dynamicIterations, gravityX, gravityY, dampingLateral,
                dampingRotational, hasSimulationArea, solver, newSleeping);
    }

    /** This world with another gravity (px/s²). */
    public WorldSpec withGravity(double newGravityX, double newGravityY) {
        return new WorldSpec(timestep, iterations, dynamicIterations, newGravityX, newGravityY, dampingLateral,
                dampingRotational, hasSimulationArea, solver, sleeping);
    }

    /** This world with other engine tunables (by SolverSettings name). */
    public WorldSpec withSolver(Map<String, Double> newSolver) {
        return new WorldSpec(timestep, iterations, dynamicIterations, gravityX, gravityY, dampingLateral,
                dampingRotational, hasSimulationArea, Map.copyOf(newSolver), sleeping);
    }
}
