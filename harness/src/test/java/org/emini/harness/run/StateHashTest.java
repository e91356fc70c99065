package org.emini.harness.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import org.emini.harness.Repo;
import org.emini.harness.Scenes;
import org.emini.harness.load.Limits;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.scenario.Scenario;
import org.junit.jupiter.api.Test;

/**
 * A scene run's state hash ({@link SceneResult#stateHash}): the same for the same run, another for a
 * changed scene, none for a run that stopped, and the same at one and two worker threads, which the
 * engine promises (World.setWorkerCount) and whose threads the run must stop.
 */
class StateHashTest {
    private static final String TOWER = String.join("\n",
            "world: {gravity: [0, GRAVITY]}",
            "shapes: {ground: {type: rectangle, width: 400, height: 20}, box: {type: rectangle, width: 20, height: 20}}",
            "bodies:",
            "  - {name: ground, shape: ground, position: [0, 10], static: true}",
            "  - {name: a, shape: box, position: [0, -11], angle: 0.1}",
            "  - {name: b, shape: box, position: [3, -33]}",
            "  - {name: c, shape: box, position: [-2, -55]}",
            "run: {duration: 2}");

    private static SceneResult tower(String gravity) {
        return ScenarioRunner.run(Scenes.valid("tower.yaml", TOWER.replace("GRAVITY", gravity)), n -> { });
    }

    @Test
    void aRunHasOneHashAndAChangedSceneAnother() {
        Long once = tower("100").stateHash();
        assertNotNull(once, "a run that ended has a hash");
        assertEquals(once, tower("100").stateHash(), "the same scene run again");
        assertNotEquals(once, tower("100.001").stateHash(), "gravity nudged by 1e-5 moves every bit of the fall");
    }

    @Test
    void aRunStoppedByAnErrorHasNoHash() {
        // The time limit stops it after its first tick: where it stops depends on the clock, so no hash.
        SceneResult r = ScenarioRunner.run(Scenes.valid("tower.yaml", TOWER.replace("GRAVITY", "100")), n -> { }, 1e-9);
        assertEquals(Status.ERROR, r.status(), r.message());
        assertNull(r.stateHash());
    }

    @Test
    void tenPyramidsAreBitIdenticalAtTwoWorkersWhoseThreadsEndWithTheRun() throws Exception {
        // 2,101 bodies and some 4,000 contacts a tick, split between the two threads. One second of it.
        String text = Files.readString(Repo.scenarios().resolve("bench/pyramids-10x20.yaml"));
        assertTrue(text.contains("duration: 10\n"), "the scene's duration, to shorten");
        ScenarioLoader.Loaded l = Scenes.load("bench/pyramids-10x20.yaml", text.replace("duration: 10\n", "duration: 1\n"));
        assertTrue(l.ok(), l.problems().toString());
        Scenario s = l.scenario();
        long before = workerThreads();
        Long alone = ScenarioRunner.run(s, n -> { }, Limits.SCENE_SECONDS, 1).stateHash();
        assertEquals(before, workerThreads(), "one worker starts no thread");
        long[] during = {0};
        // Told the ticks once, after the last one (60 < 64 ticks between calls), while the pool still runs.
        SceneResult shared = ScenarioRunner.run(s, n -> during[0] = Math.max(during[0], workerThreads()),
                Limits.SCENE_SECONDS, 2);
        assertEquals(before + 1, during[0], "the world had its one worker thread while it ticked");
        assertNotNull(alone);
        assertEquals(StateHash.hex(alone), StateHash.hex(shared.stateHash()), "two threads, the same bits");
        // Closing a pool wakes its threads to end; they do within moments (never, when nothing closes it).
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (workerThreads() > before && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        assertEquals(before, workerThreads(), "no worker thread outlives its run");
    }

    /** Live threads named as the engine's pool names its own. */
    private static long workerThreads() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.isAlive() && t.getName().startsWith("emini-worker-")).count();
    }
}
