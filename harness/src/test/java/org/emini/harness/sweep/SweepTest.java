package org.emini.harness.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
import org.emini.harness.run.Trace;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SweepTest {
    private static final String PROJECTILE = "closed-form/projectile-20hz";
    private static final String TOWER = "stacking/tower-10-20hz";

    private static int sweep(Path reports, String... extra) {
        List<String> args = new java.util.ArrayList<>(List.of("sweep", "--schema", Repo.schema().toString(),
                "--reports", reports.toString(), "--rates", "15..30", "--iterations", "5,10", "--repeats", "1",
                "--no-progress"));
        args.addAll(List.of(extra));
        args.add(Repo.scenarios().resolve(PROJECTILE + ".yaml").toString());
        args.add(Repo.scenarios().resolve(TOWER + ".yaml").toString());
        return Main.execute(args.toArray(String[]::new));
    }

    @Test
    void closedFormErrorHalvesWithTheTimestepAndSelfConsistencyIsZeroAtTheTightestSetting(@TempDir Path dir) throws Exception {
        assertEquals(0, sweep(dir));
        Map<String, SweepPoint> points = new PointStore(dir.resolve("points.jsonl")).load();
        assertEquals(8, points.size(), "2 scenes x 2 rates x 2 iteration counts, pymunk pending");
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
        StabilityMap.Map pending = StabilityMap.run(StabilityFamily.all().get(0), new OracleBackend(), List.of(15), 10);
        assertEquals(OracleBackend.PENDING, pending.note());
    }
}
