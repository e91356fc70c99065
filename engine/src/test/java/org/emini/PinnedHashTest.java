package org.emini;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The pinned determinism hash: the state of {@link EverythingScene} after a fixed number of ticks. A
 * change of this value is a change of the engine's results: make it on purpose, and say in the commit
 * why the results changed (an optimisation must leave it as it is).
 */
class PinnedHashTest {
    static final int TICKS = 400;

    @Test
    void everythingSceneWithFixedIterationsKeepsItsPinnedHash() {
        EverythingScene scene = new EverythingScene(false);
        scene.run(TICKS);
        assertEquals(PINNED_FIXED, scene.hash(), () -> String.format("new hash 0x%016XL", scene.hash()));
    }

    @Test
    void everythingSceneWithDynamicIterationsKeepsItsPinnedHash() {
        EverythingScene scene = new EverythingScene(true);
        scene.run(TICKS);
        assertEquals(PINNED_DYNAMIC, scene.hash(), () -> String.format("new hash 0x%016XL", scene.hash()));
    }

    @Test
    void theSceneTriggersEventsAndKeepsParticles() {
        EverythingScene scene = new EverythingScene(false);
        scene.run(TICKS);
        assertTrue(scene.getEventCount() > 100, "events " + scene.getEventCount());
        assertTrue(scene.world.getParticleEmitter(0).getParticleCount() > 0, "particles");
    }

    static final long PINNED_FIXED = 0x8F2A7AF191E84C88L;
    static final long PINNED_DYNAMIC = 0xE7F5FF6EE8C7E3E1L;
}
