package org.emini.harness.fuzz.world;

/** An invariant checked after every tick of a run. */
interface TickCheck {
    /** Called once, after the world is built and before the first tick. */
    void start(FuzzWorld w);

    /**
     * Checks the state after a tick.
     *
     * @param tick the tick just run, from 0
     * @return the violation, or null
     */
    Violation afterTick(FuzzWorld w, int tick);
}
