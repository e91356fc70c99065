package org.emini.harness.fuzz.world;

import org.emini.dynamics.Body;
import org.emini.dynamics.Contact;
import org.emini.world.World;
import org.emini.event.Event;
import org.emini.event.PhysicsEventListener;

/**
 * The recipe's event listener: counts and hashes what fires (for the determinism hash) and carries
 * out the recipe's listener removals. Allocation-free.
 */
final class FuzzListener implements PhysicsEventListener {
    private final World world;
    private final Body[] removed;
    private final int[] removalTicks;
    private final boolean[] done;
    private long count;
    private long hash = 17;

    FuzzListener(World world, Body[] removed, int[] removalTicks) {
        this.world = world;
        this.removed = removed;
        this.removalTicks = removalTicks;
        this.done = new boolean[removed.length];
    }

    @Override
    public void eventTriggered(Event event, Object parameter) {
        count++;
        hash = 31 * hash + event.getType();
        if (parameter instanceof Body b) {
            hash = 31 * hash + b.getId();
        } else if (parameter instanceof Contact c) {
            hash = 31 * hash + c.getBodyA().getId();
        }
        // The world counts the tick before it checks events: tick k's events see k + 1.
        long tick = world.getTickCount() - 1;
        for (int i = 0; i < removed.length; i++) {
            if (!done[i] && removalTicks[i] == tick) {
                done[i] = true;
                world.removeBody(removed[i]);
            }
        }
    }

    /** Events reported so far. */
    long count() {
        return count;
    }

    /** A hash of the events reported so far, in order. */
    long hash() {
        return 31 * hash + count;
    }
}
