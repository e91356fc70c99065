package org.emini.harness.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.emini.harness.Repo;
import org.emini.harness.cli.Main;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.load.SchemaCheck;
import org.emini.harness.oracle.OracleEnvironment;
import org.emini.harness.run.Trace;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SweepTest {
    private static final String PROJECTILE = "closed-form/projectile-20hz";
    private static final String TOWER = "stacking/tower-10-20hz";

    /** A tiny engine-only sweep of the projectile and the tower (the oracle's tests are below). */
    private static int sweep(Path reports, String... extra) {
        List<String> args = new java.util.ArrayList<>(List.of("sweep", "--schema", Repo.schema().toString(),
                "--reports", reports.toString(), "--rates", "15..30", "--iterations", "5,10", "--repeats", "1",
                "--no-progress", "--engines", "emini"));
        args.addAll(List.of(extra));
        args.add(Repo.scenarios().resolve(PROJECTILE + ".yaml").toString());
        args.add(Repo.scenarios().resolve(TOWER + ".yaml").toString());
        return Main.execute(args.toArray(String[]::new));
    }

    @Test
    void closedFormErrorHalvesWithTheTimestepAndSelfConsistencyIsZeroAtTheTightestSetting(@TempDir Path dir) throws Exception {
        assertEquals(0, sweep(dir));
        Map<String, SweepPoint> points = new PointStore(dir.resolve("points.jsonl")).load();
        assertEquals(8, points.size(), "2 scenes x 2 rates x 2 iteration counts");
        SweepPoint p15 = points.get(SweepPoint.key(PROJECTILE, "emini", 15, 10));
        SweepPoint p30 = points.get(SweepPoint.key(PROJECTILE, "emini", 30, 10));
        assertEquals("closedForm:projectile", p15.reference());
        // Symplectic Euler: the position error of a projectile is first order in h.
        assertEquals(2, p15.maxError() / p30.maxError(), 0.2);
        assertTrue(p15.costSeconds() > 0);
        assertTrue(p15.energyDrift() > 0, "a projectile conserves energy, so its drift is measured");
        SweepPoint tight = points.get(SweepPoint.key(TOWER, "emini", 30, 10));
        assertEquals("self:30/10", tight.reference());
        assertEquals(0, tight.maxError(), 0);
        assertTrue(Files.isRegularFile(dir.resolve("plots").resolve("closed-form_projectile-20hz-error.svg")));
    }

    @Test
    void aSceneWithAnElementTheEngineLacksIsStillJudgedAgainstItsClosedForm(@TempDir Path dir) throws Exception {
        ScenarioLoader ahead = new ScenarioLoader(SchemaCheck.fromFile(Repo.schemaAhead(dir)), Repo.scenarios());
        String text = Files.readString(Repo.scenarios().resolve("closed-form/pendulum-90deg.yaml"))
                .replace("reference:", "particles: [{from: [500, 500], burst: 5}]\nreference:");
        Sweep.SceneFile scene = new Sweep.SceneFile("closed-form/pendulum-90deg", text);
        EngineBackend engine = new EngineBackend(ahead);
        // Stands in for pymunk, which leaves the particles out and runs the rest.
        SweepBackend leavesOutParticles = new SweepBackend() {
            @Override
            public String name() {
                return "stand-in";
            }

            @Override
            public String unavailable() {
                return null;
            }

            @Override
            public Measured run(String sceneId, String variantText, int repeats) {
                try {
                    ObjectMapper json = new ObjectMapper();
                    ObjectNode variant = (ObjectNode) json.readTree(variantText);
                    variant.remove("particles");
                    return engine.run(sceneId, json.writeValueAsString(variant), repeats);
                } catch (java.io.IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }
        };
        Sweep sweep = new Sweep(ahead, SweepGrid.of(30, 60, List.of(5)), 1);
        assertEquals("unsupported", sweep.measure(new Sweep.Task(scene, engine, 30, 5)).status());
        SweepPoint p = sweep.measure(new Sweep.Task(scene, leavesOutParticles, 30, 5));
        assertEquals("ok", p.status(), p.message());
        assertEquals("closedForm:pendulum", p.reference(), "as compare judges it, not self-consistency");
    }

    @Test
    void aSweepResumesFromItsResultsAndShardsCoverTheGridOnce(@TempDir Path dir) throws Exception {
        assertEquals(0, sweep(dir, "--shard", "1/2", "--no-plots"));
        List<String> first = Files.readAllLines(dir.resolve("points.jsonl"), StandardCharsets.UTF_8);
        assertEquals(4, first.size());
        assertEquals(0, sweep(dir, "--shard", "1/2", "--no-plots"));
        assertEquals(4, Files.readAllLines(dir.resolve("points.jsonl")).size(), "completed points are not run again");
        // A torn last line (an interrupted write) is ignored and its point run again.
        Files.writeString(dir.resolve("points.jsonl"), "{\"scene\":\"trunc", java.nio.file.StandardOpenOption.APPEND);
        assertEquals(0, sweep(dir, "--shard", "2/2", "--no-plots"));
        Map<String, SweepPoint> points = new PointStore(dir.resolve("points.jsonl")).load();
        assertEquals(8, points.size());
        Set<String> keys = new HashSet<>(points.keySet());
        assertEquals(8, keys.size());
    }

    @Test
    void aVariantKeepsTheSceneAndChangesOnlyTheSettings() {
        ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(Repo.schema()), Repo.scenarios());
        String text = "world: {ticksPerSecond: 20}\nshapes: {b: {type: circle, radius: 5}}\n"
                + "bodies: [{name: ball, shape: b}]\nrun: {duration: 1, expect: [{noTunnelling: true}]}\n";
        String v = SceneVariant.rewrite(text, "x/ball", 1.0 / 60, 7, 1.0 / 15);
        ScenarioLoader.Loaded l = loader.load("variant", v, "ignored");
        assertTrue(l.ok(), l.problems().toString());
        assertEquals("x/ball", l.scenario().name());
        assertEquals(1.0 / 60, l.scenario().world().timestep(), 1e-15);
        assertEquals(7, l.scenario().world().iterations());
        assertEquals(0, l.scenario().run().expect().size());
        assertEquals(60, l.scenario().ticks());
    }

    @Test
    void errorAgainstATraceInterpolatesTheReferenceInTime() {
        Trace ref = new Trace(0.5, List.of("b"), List.of());
        ref.add(0, new double[] {0, 0, 0, 0, 0, 0});
        ref.add(1, new double[] {10, 0, 0, 0, 0, 0});
        Trace run = new Trace(0.25, List.of("b"), List.of());
        run.add(1, new double[] {6, 0, 0, 0, 0, 0});
        assertEquals(1, Accuracy.againstTrace(run, List.of("b"), ref)[0], 1e-12);
        double[] r = Accuracy.reduce(new double[] {1, 3, 2});
        assertEquals(2, r[0]);
        assertEquals(3, r[1]);
        assertTrue(Double.isNaN(Accuracy.reduce(new double[] {1, Double.NaN})[1]));
    }

    @Test
    void stabilityMapsFlagTunnellingAndJudgeSprings() {
        ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(Repo.schema()), Repo.scenarios());
        EngineBackend engine = new EngineBackend(loader);
        for (StabilityFamily f : StabilityFamily.all()) {
            if (f.name().equals("springStiffness")) {
                StabilityMap.Map m = StabilityMap.run(f, engine, List.of(15), 10);
                assertTrue(m.cells().stream().noneMatch(c -> c.verdict().equals("unsupported")));
            }
            if (f.name().equals("bodySpeed")) {
                StabilityMap.Map m = StabilityMap.run(f, engine, List.of(15, 30), 10);
                assertEquals(f.values().size() * 2, m.cells().size());
                assertTrue(m.cells().stream().allMatch(c -> List.of("stable", "tunnelling", "NaN").contains(c.verdict())));
                assertTrue(m.cells().stream().anyMatch(c -> c.verdict().equals("stable")));
            }
        }
    }

    // ------------------------------------------------------------------------------------------------
    // The pymunk oracle's side. It runs in oracle-py/.venv, which the harness builds from the pinned
    // requirements on first use. Without Python these tests are skipped, unless EMINI_REQUIRE_ORACLE is
    // set (./emini test sets it): CI must not skip them quietly.

    private static final String PROJECTILE_60 = "closed-form/projectile-60hz";

    private static OracleBackend oracle(Path dir) {
        return oracle(dir, "pymunk");
    }

    private static OracleBackend oracle(Path dir, String engine) {
        OracleBackend b = new OracleBackend(new OracleEnvironment(Repo.root().resolve("oracle-py"),
                OracleEnvironment.defaultPython()), Repo.schema(), dir.resolve("oracle-serve-" + engine + ".log"), System.err,
                600, engine);
        if (b.unavailable() != null) {
            b.close();
            if (System.getenv("EMINI_REQUIRE_ORACLE") != null) {
                fail("the oracle is required (EMINI_REQUIRE_ORACLE) but " + b.unavailable());
            }
            Assumptions.abort("no pymunk oracle here: " + b.unavailable());
        }
        return b;
    }

    private static int sweepBoth(Path reports, String rates, String engines, String... scenes) {
        List<String> args = new java.util.ArrayList<>(List.of("sweep", "--schema", Repo.schema().toString(),
                "--reports", reports.toString(), "--rates", rates, "--iterations", "10", "--repeats", "1",
                "--no-progress", "--engines", engines));
        for (String s : scenes) {
            args.add(Repo.scenarios().resolve(s + ".yaml").toString());
        }
        return Main.execute(args.toArray(String[]::new));
    }

    @Test
    void bothEnginesGivePointsAgainstTheClosedFormAndPymunksErrorHalvesWithTheTimestep(@TempDir Path dir) throws Exception {
        oracle(dir).close(); // skips or fails here, with the reason, when there is no oracle
        assertEquals(0, sweepBoth(dir, "15..60", "emini,pymunk", PROJECTILE_60));
        Map<String, SweepPoint> points = new PointStore(dir.resolve("points.jsonl")).load();
        assertEquals(6, points.size(), "2 engines x 3 rates x 1 iteration count");
        for (String engine : List.of("emini", "pymunk")) {
            for (int rate : List.of(15, 30, 60)) {
                SweepPoint p = points.get(SweepPoint.key(PROJECTILE_60, engine, rate, 10));
                assertEquals("ok", p.status(), p.toString());
                assertEquals("closedForm:projectile", p.reference(), p.toString());
                assertTrue(Double.isFinite(p.maxError()) && p.maxError() > 0, p.toString());
                assertTrue(Double.isFinite(p.finalError()) && Double.isFinite(p.rmsError()), p.toString());
                assertTrue(p.costSeconds() > 0 && Double.isFinite(p.costSeconds()), p.toString());
                assertTrue(p.cpuCostSeconds() > 0 && Double.isFinite(p.cpuCostSeconds()), p.toString());
                assertEquals(400, p.motion(), 1e-6, "the ball ends 400 px from where it starts");
                assertTrue(Double.isFinite(p.energyDrift()), "a projectile conserves energy: " + p);
            }
        }
        // Chipmunk moves a body with its old velocity before adding g h, so its height lags the parabola
        // by g h t / 2: 200 h px at t = 4 s, first order in h (13.3, 6.67, 3.33 px).
        double[] pymunk = new double[3];
        for (int i = 0; i < 3; i++) {
            SweepPoint p = points.get(SweepPoint.key(PROJECTILE_60, "pymunk", 15 << i, 10));
            pymunk[i] = p.maxError();
            assertEquals(200.0 / (15 << i), p.maxError(), 1e-6, "g h t / 2 at t = 4 s");
        }
        assertEquals(2, pymunk[0] / pymunk[1], 1e-6);
        assertEquals(2, pymunk[1] / pymunk[2], 1e-6);
        // Emini's ten substeps lead it by g (h / 10) t / 2 instead: ten times smaller at the same h.
        SweepPoint emini15 = points.get(SweepPoint.key(PROJECTILE_60, "emini", 15, 10));
        assertEquals(pymunk[0] / 10, emini15.maxError(), 0.05 * pymunk[0] / 10);
        assertTrue(Files.isRegularFile(dir.resolve("plots").resolve("closed-form_projectile-60hz-error.svg")));
        Map<String, List<SweepPoint>> lines = WorkPrecisionPlots.lines(List.copyOf(points.values()), SweepPoint::maxError);
        assertEquals(Set.of("emini, 10 iterations", "pymunk, 10 iterations"), lines.keySet(),
                "one line per engine and setting in the plot");
        assertEquals(3, lines.get("pymunk, 10 iterations").size());
    }

    @Test
    void pymunkPointsAreKeptPerEngineWhenASweepResumes(@TempDir Path dir) throws Exception {
        oracle(dir).close();
        assertEquals(0, sweepBoth(dir, "15..30", "emini", PROJECTILE_60));
        assertEquals(2, Files.readAllLines(dir.resolve("points.jsonl")).size());
        assertEquals(0, sweepBoth(dir, "15..30", "emini,pymunk", PROJECTILE_60));
        List<String> lines = Files.readAllLines(dir.resolve("points.jsonl"));
        assertEquals(4, lines.size(), "only pymunk's points were still to run");
        assertTrue(lines.get(2).contains("\"pymunk\"") && lines.get(3).contains("\"pymunk\""));
        // An oracle point that ended in error is run again; the others are kept.
        Files.writeString(dir.resolve("points.jsonl"), lines.get(3).replace("\"status\":\"ok\"", "\"status\":\"error\""),
                java.nio.file.StandardOpenOption.APPEND);
        Files.writeString(dir.resolve("points.jsonl"), "\n", java.nio.file.StandardOpenOption.APPEND);
        assertEquals(0, sweepBoth(dir, "15..30", "emini,pymunk", PROJECTILE_60));
        Map<String, SweepPoint> points = new PointStore(dir.resolve("points.jsonl")).load();
        assertEquals(4, points.size());
        assertTrue(points.values().stream().allMatch(p -> p.status().equals("ok")));
    }

    @Test
    void pymunkSelfConsistencyIsAgainstItsOwnTightestSetting(@TempDir Path dir) throws Exception {
        ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(Repo.schema()), Repo.scenarios());
        try (OracleBackend pymunk = oracle(dir)) {
            SweepGrid grid = SweepGrid.of(15, 30, List.of(10));
            Sweep sweep = new Sweep(loader, grid, 1);
            Sweep.SceneFile tower = Sweep.read(loader, Repo.scenarios().resolve(TOWER + ".yaml"));
            List<SweepPoint> out = new java.util.ArrayList<>();
            sweep.run(sweep.tasks(List.of(tower), List.of(pymunk), 1, 1, Set.of()), out::add);
            assertEquals(2, out.size());
            assertTrue(out.stream().allMatch(p -> p.engine().equals("pymunk") && p.reference().equals("self:30/10")));
            SweepPoint tight = out.stream().filter(p -> p.rate() == 30).findFirst().orElseThrow();
            assertEquals(0, tight.maxError(), 0, "pymunk's tightest setting is its own reference");
            SweepPoint coarse = out.stream().filter(p -> p.rate() == 15).findFirst().orElseThrow();
            assertTrue(coarse.maxError() > 0 && Double.isFinite(coarse.maxError()), coarse.toString());
        }
    }

    @Test
    void pymunkStabilityCellsStandBesideTheEnginesAndItsBulletsTunnel(@TempDir Path dir) throws Exception {
        StabilityFamily speed = StabilityFamily.all().stream().filter(f -> f.name().equals("bodySpeed")).findFirst().orElseThrow();
        try (OracleBackend pymunk = oracle(dir)) {
            StabilityMap.Map m = StabilityMap.run(speed, pymunk, List.of(60), 10);
            assertEquals("pymunk", m.engine());
            assertEquals(speed.values().size(), m.cells().size());
            // pymunk has no continuous collision: at 10^4 px/s the 2 px bullet moves 167 px a tick.
            assertEquals("stable", m.cells().get(0).verdict(), m.cells().toString());
            assertEquals("tunnelling", m.cells().get(2).verdict(), m.cells().toString());
            Path svg = dir.resolve("bodySpeed.svg");
            ScenarioLoader loader = new ScenarioLoader(SchemaCheck.fromFile(Repo.schema()), Repo.scenarios());
            StabilityMap.Map engine = StabilityMap.run(speed, new EngineBackend(loader), List.of(60), 10);
            StabilityMapImage.write(svg, speed, List.of(60), 10, List.of(engine, m));
            String text = Files.readString(svg);
            assertTrue(text.contains(">emini<") && text.contains(">pymunk<") && text.contains("tunnel"));
        }
    }

    @Test
    void box2dStabilityCellsStandWhereItsContinuousCollisionCatchesTheBullet(@TempDir Path dir) throws Exception {
        StabilityFamily speed = StabilityFamily.all().stream().filter(f -> f.name().equals("bodySpeed")).findFirst().orElseThrow();
        try (OracleBackend box2d = oracle(dir, "box2d")) {
            StabilityMap.Map m = StabilityMap.run(speed, box2d, List.of(60), 10);
            assertEquals("box2d", m.engine());
            assertTrue(box2d.versions().startsWith("Box2D 3.1.1"), box2d.versions());
            // Box2D sweeps fast bodies against static ones: at 10^2 and 10^4 px/s (167 px a tick) the 2 px bullet
            // stops at the 4 px wall, where pymunk's passes it.
            assertEquals("stable", m.cells().get(0).verdict(), m.cells().toString());
            assertEquals("stable", m.cells().get(2).verdict(), m.cells().toString());
        }
    }

    @Test
    void anOracleThatCannotBeSetUpSaysWhyAndTheSweepGoesOn(@TempDir Path dir) throws Exception {
        Path home = Files.createDirectories(dir.resolve("oracle-py"));
        Files.copy(Repo.root().resolve("oracle-py/requirements.txt"), home.resolve("requirements.txt"));
        OracleBackend broken = new OracleBackend(new OracleEnvironment(home, dir.resolve("no-such-python").toString()),
                Repo.schema(), dir.resolve("oracle-serve.log"), System.err, 60);
        String why = broken.unavailable();
        assertTrue(why != null && why.contains("cannot start") && why.contains("EMINI_PYTHON"), why);
        assertEquals("unsupported", broken.run("x", "{}", 1).status());
        StabilityMap.Map m = StabilityMap.run(StabilityFamily.all().get(0), broken, List.of(15), 10);
        assertEquals(why, m.note());
        assertTrue(m.cells().isEmpty());
        broken.close();
        // The command goes on with the engine and says why pymunk is missing.
        List<String> args = List.of("sweep", "--schema", Repo.schema().toString(), "--reports", dir.resolve("r").toString(),
                "--rates", "15..15", "--iterations", "10", "--repeats", "1", "--no-progress", "--no-plots",
                "--oracle-dir", home.toString(), "--python", dir.resolve("no-such-python").toString(),
                Repo.scenarios().resolve(PROJECTILE_60 + ".yaml").toString());
        assertEquals(0, Main.execute(args.toArray(String[]::new)));
        Map<String, SweepPoint> points = new PointStore(dir.resolve("r").resolve("points.jsonl")).load();
        assertEquals(Set.of(SweepPoint.key(PROJECTILE_60, "emini", 15, 10)), points.keySet());
    }

    /** An energy trace of 90 samples: a spring that oscillates (bounded) or keeps gaining energy. */
    private static Trace energyTrace(boolean growing) {
        Trace t = new Trace(0.1, List.of(), List.of("energy.kinetic", "energy.total"));
        for (int i = 0; i < 90; i++) {
            double wobble = 10 * Math.abs(Math.sin(i * 0.7));
            double total = 100 + wobble + (growing ? i : 0);
            t.add(i, new double[] {total, total});
        }
        return t;
    }

    @Test
    void aBoundedEnergyRiseIsAnErrorAndOnlyGrowthIsUnstable() {
        StabilityFamily springs = StabilityFamily.all().stream().filter(f -> f.name().equals("springStiffness"))
            .findFirst().orElseThrow();
        assertEquals("energy error", StabilityMap.judge(springs, 1000, 60, energyTrace(false)).verdict());
        assertEquals("energy growth", StabilityMap.judge(springs, 1000, 60, energyTrace(true)).verdict());
    }
}
