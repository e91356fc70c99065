package org.emini.harness.fuzz.world;

import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.SolverStep;

/** An application constraint that acts on no body: the base of constraints that only do something on the side. */
abstract class IdleConstraint implements Constraint {
    @Override
    public boolean concernsBody(Body b) {
        return false;
    }

    @Override
    public void warmStart(SolverStep step) {
    }

    @Override
    public float solve(SolverStep step, boolean useBias) {
        return 0f;
    }

    @Override
    public void finish(SolverStep step) {
    }

    @Override
    public float getForce() {
        return 0f;
    }
}
