package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.emini.dynamics.SolverSettings;
import org.emini.harness.Repo;
import org.emini.harness.Scenes;
import org.emini.harness.cli.Main;
import org.emini.harness.load.Problem;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.oracle.TraceReader;
import org.emini.harness.report.TraceWriter;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.Status;
import org.emini.harness.run.Trace;
import org.emini.harness.scenario.Scenario;
import org.emini.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code world.sleeping} and {@code sleepingAllowed} (issue 17): read, built through the engine's API,
 * refused where the engine would refuse them, forced by {@code run --sleeping}, and recorded in traces.
 */
class SleepingSceneTest {
    /** Ten boxes resting on the ground: they sleep after the engine's 0.5 s. */
    private static final String[] ROW = {
        "shapes: {box: {type: rectangle, width: 20, height: 20}}",
        "bodies: [{name: ground, shape: {type: rectangle, width: 400, height: 20}, position: [0, 10], static: true}]",
        "generators: [{type: row, name: box, shape: box, start: [-100, -10], count: 10, spacing: [30, 0]}]",
    };

    private static World build(String... lines) throws UnsupportedElementException {
        return WorldBuilder.build(Scenes.valid("s.yaml", lines)).world();
    }

    @Test
    void sleepingIsOffUnlessTheSceneTurnsItOn() throws Exception {
        assertFalse(build("run: {duration: 1}").isSleepingEnabled());
        assertFalse(build("world: {sleeping: false}", "run: {duration: 1}").isSleepingEnabled());
        World on = build("world: {sleeping: true}", "run: {duration: 1}");
        assertTrue(on.isSleepingEnabled());
        SolverSettings d = new SolverSettings();
        SolverSettings s = on.getSolverSettings();
        assertEquals(d.getSleepLinearTolerance(), s.getSleepLinearTolerance());
        assertEquals(d.getSleepAngularTolerance(), s.getSleepAngularTolerance());
        assertEquals(d.getTimeToSleep(), s.getTimeToSleep());
    }

    @Test
    void anObjectTurnsSleepingOnWithItsTolerances() throws Exception {
        World w = build("world: {sleeping: {linearTolerance: 2.5, angularTolerance: 0.1, timeToSleep: 1.5}}",
                "run: {duration: 1}");
        assertTrue(w.isSleepingEnabled());
        assertEquals(2.5f, w.getSolverSettings().getSleepLinearTolerance());
        assertEquals(0.1f, w.getSolverSettings().getSleepAngularTolerance());
        assertEquals(1.5f, w.getSolverSettings().getTimeToSleep());
        World partial = build("world: {sleeping: {timeToSleep: 2}}", "run: {duration: 1}");
        assertEquals(2f, partial.getSolverSettings().getTimeToSleep());
        assertEquals(new SolverSettings().getSleepLinearTolerance(), partial.getSolverSettings().getSleepLinearTolerance());
    }

    @Test
    void sleepingAllowedReachesWrittenAndGeneratedBodies() throws Exception {
        BuiltWorld w = WorldBuilder.build(Scenes.valid("a.yaml",
                "bodies:",
                "  - {name: player, shape: {type: circle, radius: 5}, sleepingAllowed: false}",
                "  - {name: crate, shape: {type: circle, radius: 5}, position: [50, 0]}",
                "generators: [{type: row, name: r, shape: {type: circle, radius: 5}, start: [100, 0], count: 2,",
                "  body: {sleepingAllowed: false}}]",
                "run: {duration: 1}"));
        assertFalse(w.body("player").isSleepingAllowed());
        assertTrue(w.body("crate").isSleepingAllowed());
        assertFalse(w.body("r[1]").isSleepingAllowed());
    }

    @Test
    void aToleranceOutOfItsBoundsIsRefusedWhereItIsWritten() {
        for (String bad : List.of("timeToSleep: 0", "linearTolerance: -1", "angularTolerance: 1001", "timeToSleep: 3601",
                "linearTolerance: 100001", "sleep: 1")) {
            ScenarioLoader.Loaded l = Scenes.load("t.yaml", "world:", "  sleeping: {" + bad + "}", "run: {duration: 1}");
            assertFalse(l.ok(), bad);
            String key = bad.substring(0, bad.indexOf(':'));
            assertTrue(l.problems().stream().anyMatch(p -> p.line() == 2 && p.path().equals("$.world.sleeping." + key)),
                    bad + ": " + l.problems());
        }
        Problem p = Scenes.onlyProblem(Scenes.load("b.yaml", "bodies: [{shape: {type: circle, radius: 1},",
                "  sleepingAllowed: 0}]", "run: {duration: 1}"));
        assertEquals("$.bodies[0].sleepingAllowed", p.path());
        assertEquals(2, p.line());
    }

    /**
     * The loader accepts a tolerance exactly when the engine's setter does (validate builds the world, so a
     * value the schema let through and the engine refused would be reported there, located; none is).
     */
    @Test
    void theLoaderAcceptsExactlyWhatTheEngineAccepts() throws Exception {
        for (String key : List.of("linearTolerance", "angularTolerance", "timeToSleep")) {
            for (String v : List.of("0", "-0.0", "1e-46", "1.4e-45", "1e-30", "0.5", "1000", "3600", "100000", "3.4e38")) {
                ScenarioLoader.Loaded l = Scenes.load("v.yaml", "world: {sleeping: {" + key + ": " + v + "}}",
                        "run: {duration: 1}");
                boolean engine = engineAccepts(key, (float) Double.parseDouble(v));
                if (l.ok()) {
                    assertTrue(engine, key + " " + v + " was accepted by the loader but the engine refuses it");
                    WorldBuilder.build(l.scenario());
                } else if (engine) {
                    // Refused by the scene's bounds (documented in the schema), not by the engine: still located.
                    assertTrue(l.problems().stream().allMatch(p -> p.line() == 1), l.problems().toString());
                }
            }
        }
    }

    private static boolean engineAccepts(String key, float v) {
        SolverSettings s = new SolverSettings();
        try {
            switch (key) {
                case "linearTolerance" -> s.setSleepLinearTolerance(v);
                case "angularTolerance" -> s.setSleepAngularTolerance(v);
                default -> s.setTimeToSleep(v);
            }
            return true;
        } catch (IllegalArgumentException e) {
            return false;
        }
    }

    @Test
    void forcingSleepingKeepsTheScenesTolerances() {
        Scenario s = Scenes.valid("f.yaml", "world: {sleeping: {timeToSleep: 2}}", "run: {duration: 1}");
        assertFalse(s.withSleeping(false).world().sleeping().enabled());
        assertEquals(2, s.withSleeping(false).withSleeping(true).world().sleeping().timeToSleep());
        assertTrue(Scenes.valid("g.yaml", "run: {duration: 1}").withSleeping(true).world().sleeping().enabled());
    }

    @Test
    void theTraceSaysWhichBodiesSleptAndReadsBack() throws Exception {
        Scenario s = Scenes.valid("row.yaml", ROW[0], ROW[1], ROW[2], "world: {sleeping: true}",
                "run: {duration: 2, record: {every: 0.25, bodies: dynamic, metrics: [sleeping]}}");
        SceneResult r = ScenarioRunner.run(s, n -> { });
        assertEquals(Status.PASS, r.status(), r.message());
        Trace t = r.trace();
        assertTrue(t.recordsSleeping());
        // At rest from the start: asleep from 0.5 s (the engine's time to sleep), each box on its own.
        assertFalse(t.sleeping(0, 0));
        assertTrue(t.sleeping(t.size() - 1, 9));
        assertEquals(10, r.mostAsleep());
        assertEquals(10, t.column("sleeping.count")[t.size() - 1]);
        assertEquals(1, t.column("sleeping.fraction")[t.size() - 1]);
        StringWriter out = new StringWriter();
        TraceWriter.write(out, "row", "emini", t);
        JsonObject doc = JsonParser.parseString(out.toString()).getAsJsonObject();
        assertEquals(1, doc.getAsJsonObject("bodies").getAsJsonObject("box[3]").getAsJsonArray("sleeping")
                .get(t.size() - 1).getAsInt());
        Trace back = TraceReader.parse(doc, "row").trace();
        assertTrue(back.recordsSleeping());
        for (int i = 0; i < t.size(); i++) {
            for (int b = 0; b < t.bodies().size(); b++) {
                assertEquals(t.sleeping(i, b), back.sleeping(i, b));
            }
        }
        // Without sleeping the trace has no such column, as before.
        SceneResult off = ScenarioRunner.run(s.withSleeping(false), n -> { });
        assertFalse(off.trace().recordsSleeping());
        assertEquals(-1, off.mostAsleep());
        assertEquals(0, off.trace().column("sleeping.count")[off.trace().size() - 1]);
        StringWriter plain = new StringWriter();
        TraceWriter.write(plain, "row", "emini", off.trace());
        assertFalse(plain.toString().contains("sleeping\":["));
    }

    @Test
    void runForcesSleepingOnEveryScene(@TempDir Path dir) throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        // The scene says nothing about sleeping and expects its boxes to sleep: it passes only when forced on.
        Files.writeString(scenes.resolve("row.yaml"), String.join("\n", ROW) + "\n"
                + "run: {duration: 2, expect: [{metric: sleeping.count, of: final, near: 10, tolerance: 0}]}\n");
        Path on = dir.resolve("on");
        assertEquals(0, Main.execute("run", "--schema", Repo.schema().toString(), "--reports", on.toString(),
                "--no-progress", "--sleeping", "on", scenes.toString()));
        JsonObject scene = JsonParser.parseString(Files.readString(on.resolve("results.json"))).getAsJsonObject()
                .getAsJsonArray("scenes").get(0).getAsJsonObject();
        assertEquals(10, scene.get("mostAsleep").getAsInt());
        assertTrue(Files.readString(on.resolve("summary.txt")).contains("bodies fell asleep in 1 of the 1 scenes"));
        assertEquals(1, Main.execute("run", "--schema", Repo.schema().toString(), "--reports",
                dir.resolve("scene").toString(), "--no-progress", scenes.toString()));
        assertEquals(2, Main.execute("run", "--schema", Repo.schema().toString(), "--reports",
                dir.resolve("bad").toString(), "--no-progress", "--sleeping", "maybe", scenes.toString()));
    }
}
