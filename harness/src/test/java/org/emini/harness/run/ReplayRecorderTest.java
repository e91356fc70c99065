package org.emini.harness.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import org.emini.harness.Scenes;
import org.junit.jupiter.api.Test;

/** The replay holds every body (recorded or not), joints' anchors, the landscape, at most 300 frames. */
class ReplayRecorderTest {
    private static JsonObject replay(double seconds) {
        SceneResult r = ScenarioRunner.run(Scenes.valid("replay.yaml",
                "shapes: {ball: {type: circle, radius: 10}, pin: {type: rectangle, width: 4, height: 4}}",
                "bodies:",
                "  - {name: pivot, shape: pin, position: [0, -200], static: true}",
                "  - {name: bob, shape: ball, position: [100, -200]}",
                "  - {name: faller, shape: ball, position: [300, -100]}",
                "joints:",
                "  - {bodyA: pivot, bodyB: bob, at: [0, -200]}",
                "landscape: {segments: [{from: [-400, 0], to: [400, 0]}]}",
                "run: {duration: " + seconds + ", record: {bodies: [bob]}}"), n -> { });
        assertTrue(r.replay() != null, "a small scene gets a replay");
        return r.replay().json();
    }

    @Test
    void everyBodyLandscapeAndJointAnchorsAreRecorded() {
        JsonObject j = replay(2);
        JsonObject bodies = j.getAsJsonObject("bodies");
        assertTrue(bodies.has("faller") && bodies.has("pivot"), "bodies the scene does not record are in the replay");
        JsonArray y = bodies.getAsJsonObject("faller").getAsJsonArray("y");
        // The faller drops freely until it lands on the segment at y = 0 (its centre at -10).
        assertTrue(y.get(y.size() - 1).getAsDouble() > -20, "the faller fell to the landscape: " + y.get(y.size() - 1));
        assertEquals("[[-400.0,0.0,400.0,0.0]]", j.getAsJsonArray("landscape").toString());
        assertEquals("[\"joint\"]", j.getAsJsonArray("constraints").toString());
        JsonArray first = j.getAsJsonArray("anchors").get(0).getAsJsonArray();
        // Both anchors at the pin's point at the start.
        assertEquals(0, first.get(0).getAsDouble(), 1e-3);
        assertEquals(-200, first.get(1).getAsDouble(), 1e-3);
        assertEquals(0, first.get(2).getAsDouble(), 1e-3);
        assertEquals(-200, first.get(3).getAsDouble(), 1e-3);
    }

    @Test
    void longRunsKeepAtMostMaxFramesWithTheFirstAndLastTick() {
        JsonObject j = replay(60);  // 1200 ticks at the default 20 ticks/s
        JsonArray time = j.getAsJsonArray("time");
        assertTrue(time.size() <= ReplayRecorder.MAX_FRAMES, time.size() + " frames");
        assertTrue(time.size() >= ReplayRecorder.MAX_FRAMES / 2, time.size() + " frames");
        assertEquals(0, time.get(0).getAsDouble(), 0);
        assertEquals(60, time.get(time.size() - 1).getAsDouble(), 1e-6);
        assertEquals(time.size(), j.getAsJsonObject("bodies").getAsJsonObject("bob").getAsJsonArray("x").size());
    }
}
