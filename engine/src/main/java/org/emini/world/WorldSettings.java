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
        SolverSettings a = from.getSolverSettings();
        SolverSettings b = to.getSolverSettings();
        // The length scale first: it rescales the tolerances, which are then set as they are.
        b.setLengthScale(a.getLengthScale());
        b.setLinearSlop(a.getLinearSlop());
        b.setSpeculativeDistance(a.getSpeculativeDistance());
        b.setAabbMargin(a.getAabbMargin());
        b.setContactHertz(a.getContactHertz());
        b.setContactDampingRatio(a.getContactDampingRatio());
        b.setContactPushMaxVelocity(a.getContactPushMaxVelocity());
        b.setJointPushMaxVelocity(a.getJointPushMaxVelocity());
        b.setRestitutionThreshold(a.getRestitutionThreshold());
        b.setConvergenceTolerance(a.getConvergenceTolerance());
        b.setJointHertz(a.getJointHertz());
        b.setJointDampingRatio(a.getJointDampingRatio());
        b.setImpactTolerance(a.getImpactTolerance());
        b.setImpactRelaxPasses(a.getImpactRelaxPasses());
        b.setTimeOfImpactTarget(a.getTimeOfImpactTarget());
        b.setSubstepHertzRatio(a.getSubstepHertzRatio());
        b.setBlockConditionLimit(a.getBlockConditionLimit());
        b.setMaxContacts(a.getMaxContacts());
        b.setSleepLinearTolerance(a.getSleepLinearTolerance());
        b.setSleepAngularTolerance(a.getSleepAngularTolerance());
        b.setTimeToSleep(a.getTimeToSleep());
    }
}
