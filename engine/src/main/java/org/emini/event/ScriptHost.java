package org.emini.event;

import org.emini.dynamics.Body;

/** A world that runs scripts: where an event with a {@link Script} starts it ({@code World} is one). */
public interface ScriptHost {
    /**
     * Starts a script on a body, from its first element, at the start of the next tick. A body may
     * run several scripts (each start is a run of its own, as in the original).
     *
     * @param script the script
     * @param body a body of this world
     */
    void applyScript(Script script, Body body);
}
