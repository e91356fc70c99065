package org.emini.bench.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonNull;
import com.google.gson.JsonObject;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.emini.bench.engine.Engines;
import org.emini.bench.report.Charts;
import org.emini.bench.scene.BenchScenes;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Scenario;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The out-of-process engines' result files: their snapshots are judged by the benchmark's scene check,
 * in px or converted from the metre-based peers' frame, and {@code --resume} reuses a file only when it
 * covers every scene asked for.
 */
class ExternalBenchTest {
    private static final BenchScenes SCENES = BenchScenes.open();
    private static final String PYRAMID = "bench/pyramid-20";

    @Test
    void everyEngineOfAFullRunHasAColourOfItsOwnInThePlots() {
        // Seven colours for eight engines made Emini and Rapier the same red.
        int engines = Engines.ALL.size() + ExternalBench.IDS.size();
        assertTrue(Charts.colourCount() >= engines, Charts.colourCount() + " colours for " + engines + " engines");
    }

    /** A driver's entry for the pyramid whose bodies never moved, in px or metres; box 1 moved by dx px at the check. */
    private static JsonObject entry(String engine, boolean metres, double dx) {
        Scenario s = SCENES.load(PYRAMID);
        JsonObject e = new JsonObject();
        e.addProperty("scene", PYRAMID);
        e.addProperty("engine", engine);
        e.addProperty("status", "ok");
        e.addProperty("units", metres ? "m" : "px");
        e.addProperty("msPerTick", 0.3);
        e.addProperty("cpuMsPerTick", 0.28);
        e.addProperty("settings", "test");
        e.add("initial", snapshot(s, 0, metres, 0));
        e.add("check", snapshot(s, 600, metres, dx));
        e.add("afterRun", snapshot(s, 900, metres, 0));
        return e;
    }

    private static JsonObject snapshot(Scenario s, long ticks, boolean metres, double dx) {
        JsonArray poses = new JsonArray(), speeds = new JsonArray(), omegas = new JsonArray();
        for (int i = 0; i < s.bodies().size(); i++) {
            BodySpec b = s.bodies().get(i);
            double x = b.x() + (i == 1 ? dx : 0);
            poses.add(metres ? x / 20 : x);
            poses.add(metres ? -b.y() / 20 : b.y());
            poses.add(metres ? -b.state().angle() : b.state().angle());
            speeds.add(0.0);
            omegas.add(0.0);
        }
        JsonObject o = new JsonObject();
        o.addProperty("ticks", ticks);
        o.add("poses", poses);
        o.add("speeds", speeds);
        o.add("omegas", omegas);
        o.add("particles", new JsonArray());
        o.addProperty("asleep", -1);
        return o;
    }

    @Test
    void snapshotsAreJudgedInPxOrConvertedFromMetres() {
        Scenario s = SCENES.load(PYRAMID);
        for (boolean metres : new boolean[] {false, true}) {
            Measurement m = ExternalBench.measurement(entry("box2d-v3", metres, 0), s);
            assertEquals("ok", m.status());
            assertEquals("stable", m.verdict(), m.check().toString());
            assertEquals(600.0, ((Number) m.check().get("ticks")).doubleValue());
            assertEquals(0.28, m.cost());
            assertEquals(0.28 * 1000 / 210, m.usPerBody(), 1e-9);
            // 30 px sideways is more than a 20 px box: collapsed, in either unit.
            Measurement moved = ExternalBench.measurement(entry("box2d-v3", metres, 30), s);
            assertEquals("collapsed", moved.verdict(), moved.check().toString());
            assertEquals(30.0, ((Number) moved.check().get("maxDxPx")).doubleValue(), 1e-6);
        }
    }

    @Test
    void aLostBodyIsNonFiniteAndAWrongCountIsAnError() {
        Scenario s = SCENES.load(PYRAMID);
        JsonObject e = entry("rapier", true, 0);
        e.getAsJsonObject("check").getAsJsonArray("poses").set(3, JsonNull.INSTANCE);
        assertEquals("non-finite", ExternalBench.measurement(e, s).verdict());
        e.getAsJsonObject("check").getAsJsonArray("speeds").remove(0);
        assertThrows(IllegalArgumentException.class, () -> ExternalBench.measurement(e, s));
        JsonObject refused = new JsonObject();
        refused.addProperty("scene", PYRAMID);
        refused.addProperty("engine", "rapier");
        refused.addProperty("status", "unsupported");
        refused.addProperty("message", "no particles");
        Measurement m = ExternalBench.measurement(refused, s);
        assertEquals("unsupported", m.status());
        assertEquals("no particles", m.message());
    }

    @Test
    void keptResultsAreReusedOnlyWhenTheyCoverEveryScene(@TempDir Path dir) throws Exception {
        JsonArray all = new JsonArray();
        all.add(entry("pymunk", false, 0));
        JsonObject failed = new JsonObject();
        failed.addProperty("scene", "bench/tumbler");
        failed.addProperty("engine", "pymunk");
        failed.addProperty("status", "error");
        failed.addProperty("message", "failed");
        all.add(failed);
        Path f = Files.writeString(dir.resolve("pymunk.json"), all.toString(), StandardCharsets.UTF_8);

        List<Measurement> kept = ExternalBench.kept("pymunk", f, SCENES, List.of(PYRAMID));
        assertEquals(1, kept.size());
        assertEquals("stable", kept.get(0).verdict());
        ExternalBench.Outcome o = ExternalBench.run("pymunk", SCENES, BenchPlan.FULL, dir, List.of(PYRAMID), true);
        assertEquals("ran", o.status());
        assertEquals(true, o.kept(), "the report says the run was resumed");
        assertEquals(0.28, o.measurements().get(0).cost());

        assertNull(ExternalBench.kept("pymunk", f, SCENES, List.of(PYRAMID, "bench/rain-5000")), "a scene it does not have");
        assertNull(ExternalBench.kept("pymunk", f, SCENES, List.of("bench/tumbler")), "a scene that failed");
        Files.writeString(f, "[{\"scene\": ", StandardCharsets.UTF_8);
        assertNull(ExternalBench.kept("pymunk", f, SCENES, List.of(PYRAMID)), "a damaged file");
        assertNull(ExternalBench.kept("pymunk", dir.resolve("none.json"), SCENES, List.of(PYRAMID)), "no file");
    }
}
