package org.emini.world;

import org.emini.dynamics.SolverSettings;

/** Copies a world's settings for {@link World#World(World)}: the tick, gravity, damping, area and solver tuning. */
final class WorldSettings {
    private WorldSettings() {
    }

    static void copy(World from, World to) {
        to.setTimestep(from.getTimestep());
        to.setConstraintIterations(from.getConstraintIterations());
        to.setConstraintIterationDynamic(from.isConstraintIterationDynamic());
        to.setGravity(from.getGravityX(), from.getGravityY());
        to.setDampingLateral(from.getDampingLateral());
        to.setDampingRotational(from.getDampingRotational());
        if (from.hasSimulationArea()) {
            to.setSimulationArea(from.getSimulationAreaMinX(), from.getSimulationAreaMinY(), from.getSimulationAreaMaxX(),
                from.getSimulationAreaMaxY());
        }
        to.setSleepingEnabled(from.isSleepingEnabled());
        to.setHitEventThreshold(from.getHitEventThreshold());
        to.getSolverSettings().set(from.getSolverSettings());
    }
}
