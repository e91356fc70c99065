package org.emini.dynamics;

/**
 * Decides, each tick, whether a touching contact takes part in the solve: one-way platforms (let a
 * body through from below), ghost bodies, conditional collisions. Called during {@link Simulation#tick()}
 * after the narrowphase, for every contact of the simulated bodies that has points, in a fixed
 * order. It may read the contact and its bodies (their state as the tick began) and may add or
 * remove bodies (applied when the tick ends); it should not allocate, so ticks stay garbage-free.
 */
public interface PreSolveListener {
    /**
     * @param contact a contact with points (valid during the call)
     * @return true to solve it this tick, false to let its bodies pass through each other for this
     *     tick (its impulses are dropped, so it starts afresh when enabled again)
     */
    boolean preSolve(Contact contact);
}
