package org.emini.bench.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import org.emini.bench.scene.BenchScenes;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Scenario;
import org.junit.jupiter.api.Test;

/** The flat scene the out-of-process peers read is PeerScene's mapping, and their poses come back in px. */
class PeerSceneExportTest {
    private static final BenchScenes SCENES = BenchScenes.open();

    @Test
    void thePyramidIsMetresYUpWithSharedShapes() throws Exception {
        Scenario s = SCENES.load("bench/pyramid-20");
        JsonObject o = PeerSceneExport.toJson("bench/pyramid-20", s, "box2d-v3", 8);
        assertEquals("emini-peer-scene", o.get("format").getAsString());
        assertEquals("bench/pyramid-20", o.get("scene").getAsString());
        assertEquals(s.ticks(), o.get("ticks").getAsLong());
        assertEquals(-10.0, o.getAsJsonArray("gravity").get(1).getAsDouble(), 1e-12);
        assertEquals(false, o.get("sleeping").getAsBoolean());
        JsonArray bodies = o.getAsJsonArray("bodies");
        assertEquals(s.bodies().size(), bodies.size());
        // 210 boxes of one shape and the ground: two shapes written.
        assertEquals(2, o.getAsJsonArray("shapes").size());
        double[] poses = new double[3 * bodies.size()];
        for (int i = 0; i < bodies.size(); i++) {
            JsonObject b = bodies.get(i).getAsJsonObject();
            poses[3 * i] = b.get("x").getAsDouble();
            poses[3 * i + 1] = b.get("y").getAsDouble();
            poses[3 * i + 2] = b.get("angle").getAsDouble();
        }
        PeerSceneExport.toScene(poses, new double[0], new double[0], new double[0]);
        for (int i = 0; i < s.bodies().size(); i++) {
            BodySpec b = s.bodies().get(i);
            assertEquals(b.x(), poses[3 * i], 1e-9);
            assertEquals(b.y(), poses[3 * i + 1], 1e-9);
            assertEquals(b.state().angle(), poses[3 * i + 2], 1e-12);
        }
        JsonObject box = o.getAsJsonArray("shapes").get(bodies.get(1).getAsJsonObject().get("shape").getAsInt())
            .getAsJsonArray().get(0).getAsJsonObject();
        assertEquals(4, box.getAsJsonArray("vertices").size());
        assertEquals(0.64, box.get("friction").getAsDouble(), 1e-12, "squared for √(fA·fB) mixing, as PeerScene");
    }

    @Test
    void theTumblersMotorDrivesItsPivotJoint() throws Exception {
        JsonObject o = PeerSceneExport.toJson("bench/tumbler", SCENES.load("bench/tumbler"), "rapier", Integer.MAX_VALUE);
        JsonObject motor = o.getAsJsonArray("motors").get(0).getAsJsonObject();
        JsonObject joint = o.getAsJsonArray("joints").get(motor.get("joint").getAsInt()).getAsJsonObject();
        JsonObject a = o.getAsJsonArray("bodies").get(joint.get("a").getAsInt()).getAsJsonObject();
        JsonObject b = o.getAsJsonArray("bodies").get(joint.get("b").getAsInt()).getAsJsonObject();
        assertTrue(!a.get("dynamic").getAsBoolean() || !b.get("dynamic").getAsBoolean(), "pinned to a static body");
        assertEquals(4, o.getAsJsonArray("shapes").get(b.get("dynamic").getAsBoolean() ? b.get("shape").getAsInt()
            : a.get("shape").getAsInt()).getAsJsonArray().size(), "the box's four walls, one part each");
        assertEquals(0, o.get("emitters").getAsInt());
    }

    @Test
    void snapshotsComeBackInTheScenesUnits() {
        double[] poses = {1, 2, 0.5};
        double[] speeds = {3};
        double[] omegas = {0.25};
        double[] particles = {1, -1};
        PeerSceneExport.toScene(poses, speeds, omegas, particles);
        assertEquals(20, poses[0], 1e-12);
        assertEquals(-40, poses[1], 1e-12);
        assertEquals(-0.5, poses[2], 1e-12);
        assertEquals(60, speeds[0], 1e-12);
        assertEquals(-0.25, omegas[0], 1e-12);
        assertEquals(20, particles[0], 1e-12);
        assertEquals(20, particles[1], 1e-12);
    }

    @Test
    void tooManyVerticesIsUnsupported() {
        assertThrows(UnsupportedSceneException.class,
            () -> PeerSceneExport.toJson("bench/rain-100", SCENES.load("bench/rain-100"), "box2d-v3", 3));
    }
}
