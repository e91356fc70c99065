package org.emini.event;

import org.emini.world.World;

/** Helpers for the event tests. */
final class Rigs {
    private Rigs() {
    }

    static void runTicks(World world, int ticks) {
        for (int i = 0; i < ticks; i++) {
            world.tick();
        }
    }
}
