package org.emini.dynamics;

/**
 * A constraint solved together with the contacts: joints, springs and motors implement it, and so can
 * an application's own constraints (the manual's "implementing the interface constraint").
 *
 * <p>Each tick the world calls {@link #prepare} once, then for every substep {@link #warmStart}, a
 * biased {@link #solve} (which may correct position error), and after the positions have moved an
 * unbiased {@link #solve} (which must not), and finally {@link #finish}. All velocity access goes
 * through the {@link SolverStep}, which holds the bodies' state for the tick. Implementations must
 * not allocate in these calls.
 *
 * <p>Accumulated impulses are impulses per substep. When {@link SolverStep#getSubstep()} differs
 * from the substep an impulse was accumulated over (the timestep or iteration count changed),
 * scale it by the ratio before warm starting with it.
 */
public interface Constraint {
    /**
     * Whether this constraint acts on a body; a body's removal removes its constraints.
     *
     * @param body the body
     * @return true when the constraint involves it
     */
    boolean concernsBody(Body body);

    /**
     * The number of bodies this constraint acts on, so that sleeping bodies joined by it sleep and
     * wake together. The default, −1, means unknown: then every body it concerns stays awake.
     *
     * @return the count, or −1
     */
    default int getBodyCount() {
        return -1;
    }

    /**
     * A body this constraint acts on.
     *
     * @param index 0 to {@link #getBodyCount()} − 1
     * @return the body
     */
    default Body getBody(int index) {
        throw new IndexOutOfBoundsException("Constraint.getBody: index " + index + " of " + getBodyCount());
    }

    /**
     * Computes what stays fixed over the tick (anchors, effective masses) and applies nothing yet.
     *
     * @param step the tick's solver state
     */
    void prepare(SolverStep step);

    /**
     * Re-applies the impulse accumulated so far, at the start of each substep.
     *
     * @param step the tick's solver state
     */
    void warmStart(SolverStep step);

    /**
     * One Gauss–Seidel pass over this constraint.
     *
     * @param step the tick's solver state
     * @param useBias true for the pass that corrects position error, false for the relax pass
     * @return for the relax pass ({@code useBias} false): how far the substep's impulse now differs
     *     from the one it was warm-started with, as relative velocity (px/s, or rad/s times a length).
     *     Dynamic iterations stop solving once this is below the tolerance for every constraint and
     *     contact, and repeat the warm start alone in the remaining substeps, so a constraint that
     *     reports less than its real change is launched by its own impulse. The biased pass's
     *     value is not used.
     */
    float solve(SolverStep step, boolean useBias);

    /**
     * Called once after the substeps: store what the next tick warm-starts from and what
     * {@link #getForce()} reports.
     *
     * @param step the tick's solver state
     */
    void finish(SolverStep step);

    /**
     * The force past which the constraint breaks: when {@link #getForce()} exceeds it after a tick,
     * the world removes the constraint as the tick ends and lists it in
     * {@link StepData#getBrokenConstraint(int)}. The default never breaks.
     *
     * @return the force (the unit of {@link #getForce()}), Float.POSITIVE_INFINITY for unbreakable
     */
    default float getBreakForce() {
        return Float.POSITIVE_INFINITY;
    }

    /**
     * The magnitude of the force (or torque, for angular constraints) this constraint exerted in
     * the last tick, for events and for the application.
     *
     * @return the force (mass·px/s²), or torque (mass·px²/s²)
     */
    float getForce();

    /**
     * A copy of this constraint for a copied world (the original's {@code copy(Body[])}): the same
     * settings on the copies of its bodies, with no accumulated impulse. The copy is not yet in a
     * world; its bodies already are. The built-in constraints of the manual ({@code Joint},
     * {@code Spring}, {@code Motor}) implement it; the default refuses, naming the class, so a
     * world holding a constraint that cannot be copied is not copied without it.
     *
     * @param mapping the copies of the bodies
     * @return the copy
     * @throws UnsupportedOperationException when this constraint cannot be copied
     */
    default Constraint copy(CopyMapping mapping) {
        throw new UnsupportedOperationException(getClass().getName() + ".copy: this constraint cannot be copied; override"
            + " Constraint.copy(CopyMapping) to copy a world that holds it");
    }

    /**
     * The application's object attached to this constraint (the original's
     * {@code Constraint.getUserData}). The built-in constraints keep one ({@code setUserData});
     * the default has none.
     *
     * @return the user data, or null
     */
    default Object getUserData() {
        return null;
    }
}
