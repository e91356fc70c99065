package org.emini.harness.oracle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.DoubleUnaryOperator;
import org.emini.harness.Scenes;
import org.emini.harness.closedform.ClosedForm;
import org.emini.harness.run.Trace;
import org.emini.harness.scenario.Scenario;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Rows, references and verdicts of the engine–oracle comparison, on hand-made traces. */
class ComparisonTest {
    private static final OracleScene OK = new OracleScene("f", "s", "ok", "", List.of(), List.of(), "t");

    /** A trace of one body moving along x as x(t), and the listed metric channels as given functions of t. */
    private static Trace trace(DoubleUnaryOperator x, Map<String, DoubleUnaryOperator> metrics) {
        List<String> channels = List.copyOf(metrics.keySet());
        Trace t = new Trace(0.1, List.of("ball"), channels);
        for (int k = 0; k <= 10; k++) {
            double time = k * 0.1;
            double[] row = new double[6 + channels.size()];
            row[0] = x.applyAsDouble(time);
            row[3] = 10;
            for (int c = 0; c < channels.size(); c++) {
                row[6 + c] = metrics.get(channels.get(c)).applyAsDouble(time);
            }
            t.add(k, row);
        }
        return t;
    }

    private static Comparison.Row row(Comparison.Scene s, String channel) {
        return s.rows().stream().filter(r -> r.channel().equals(channel)).findFirst()
                .orElseThrow(() -> new AssertionError("no row " + channel + " in " + s.rows()));
    }

    private static final String ISOLATED = String.join("\n",
            "world: {gravity: [0, 0]}",
            "bodies: [{name: ball, shape: {type: circle, radius: 5}, velocity: [10, 0]}]",
            "run: {duration: 1, record: {every: 0.1, metrics: [linearMomentum, penetration]}}");

    @Test
    void anIsolatedSceneJudgesMomentumDriftAgainstZeroAndPenetrationAgainstRigidity() {
        Scenario s = Scenes.valid("iso.yaml", ISOLATED);
        Trace engine = trace(t -> 10 * t, Map.of("momentum.x", t -> 10 + 0.5 * t, "momentum.y", t -> 0,
                "penetration.max", t -> 0.05, "penetration.mean", t -> 0.02, "penetration.points", t -> 2));
        Trace oracle = trace(t -> 10 * t, Map.of("momentum.x", t -> 10, "momentum.y", t -> 0,
                "penetration.max", t -> 0.5, "penetration.mean", t -> 0.2, "penetration.points", t -> 2));
        Comparison.Scene c = Comparison.compare(s, "pass", engine, OK, oracle, null);
        assertEquals(CompareStatus.COMPARED, c.status());
        Comparison.Row momentum = row(c, "momentum.x");
        assertEquals("maxDrift", momentum.figure());
        assertEquals(0.5, momentum.engine(), 1e-12);
        assertEquals(0, momentum.oracle(), 1e-12);
        assertEquals("law: an isolated system keeps its momentum", momentum.referenceSource());
        assertEquals(Closer.ORACLE, momentum.closer());
        // Default tolerance max(0.01, 2% of 10.5) = 0.21 < 0.5: the drifts differ.
        assertEquals(Agreement.DIFFER, momentum.agreement());
        Comparison.Row pen = row(c, "penetration.max");
        assertEquals(Closer.ENGINE, pen.closer());
        assertEquals(Agreement.DIFFER, pen.agreement());  // 0.45 > 0.25 px
        assertEquals(Agreement.AGREE, row(c, "penetration.mean").agreement());  // 0.02 against 0.2: within 0.25 px
    }

    @Test
    void aSceneWithAOneSidedSegmentHasNoLawForTunnelling() {
        // elements/one-sided-floor: a ball rising through the open side is the scene's point; the
        // oracle's segments are two-sided, so its count of 0 is not closer to any truth.
        String wall = "      - tunnelling: {walls: [{from: [-200, 0], to: [200, 0]}]}";
        String body = String.join("\n",
                "bodies: [{name: ball, shape: {type: circle, radius: 5}, velocity: [10, 0]}]",
                "landscape: {segments: [{from: [-200, 0], to: [200, 0]FACE}]}",
                "run:",
                "  duration: 1",
                "  record:",
                "    every: 0.1",
                "    metrics:",
                wall);
        Trace engine = trace(t -> 10 * t, Map.of("tunnelling.count", t -> t > 0.5 ? 1 : 0));
        Trace oracle = trace(t -> 10 * t, Map.of("tunnelling.count", t -> 0));
        Comparison.Row oneSided = row(Comparison.compare(Scenes.valid("one.yaml", body.replace("FACE", ", face: left")),
                "pass", engine, OK, oracle, null), "tunnelling.count");
        assertEquals(null, oneSided.referenceSource());
        assertEquals(Closer.NONE, oneSided.closer());
        Comparison.Row twoSided = row(Comparison.compare(Scenes.valid("two.yaml", body.replace("FACE", "")),
                "pass", engine, OK, oracle, null), "tunnelling.count");
        assertEquals("law: no body passes through a wall", twoSided.referenceSource());
        assertEquals(Closer.ORACLE, twoSided.closer());
    }

    @Test
    void reportsWriteTheVerdictsInTheWordsTheDashboardReads(@TempDir Path dir) throws Exception {
        Scenario s = Scenes.valid("iso.yaml", ISOLATED);
        Trace engine = trace(t -> 10 * t, Map.of("momentum.x", t -> 10 + 0.5 * t, "momentum.y", t -> 0));
        Trace oracle = trace(t -> 10 * t, Map.of("momentum.x", t -> 10, "momentum.y", t -> 0));
        List<MultiComparison.Scene> scenes = List.of(
                MultiComparison.merge(Map.of("pymunk", Comparison.compare(s, "pass", engine, OK, oracle, null))),
                MultiComparison.merge(Map.of("pymunk", Comparison.compare(s, "unsupported: joints", null, OK, oracle, null))));
        MultiComparison.write(dir, scenes, MultiComparison.Summary.of(scenes, List.of("pymunk"), 1), "test",
                List.of("pymunk"), "pymunk");
        com.google.gson.JsonObject json = com.google.gson.JsonParser.parseString(
                Files.readString(dir.resolve("compare.json"))).getAsJsonObject();
        assertEquals("{\"compared\":1,\"oracle only\":1}",
                json.getAsJsonObject("summary").getAsJsonObject("status").getAsJsonObject("pymunk").toString());
        com.google.gson.JsonArray out = json.getAsJsonArray("scenes");
        assertEquals("oracle only", out.get(1).getAsJsonObject().get("status").getAsString());
        java.util.Set<String> agreements = new java.util.TreeSet<>();
        java.util.Set<String> closers = new java.util.TreeSet<>();
        for (com.google.gson.JsonElement scene : out) {
            for (com.google.gson.JsonElement r : scene.getAsJsonObject().getAsJsonArray("rows")) {
                com.google.gson.JsonObject row = r.getAsJsonObject();
                agreements.add(row.getAsJsonObject("oracles").getAsJsonObject("pymunk").get("agreement").getAsString());
                closers.add(row.get("closer").getAsString());
            }
        }
        assertEquals(java.util.Set.of("-", "agree", "differ"), agreements);
        // The closer is named by engine: here the oracle, a tie, or none (no reference).
        assertEquals(java.util.Set.of("-", "pymunk", "tie"), closers);
        String md = Files.readString(dir.resolve("summary.md"));
        assertTrue(md.contains("| momentum.x | maxDrift | 0.5 | 0 | 0.5 | 0.21 | differ | 0 (law: an isolated system keeps "
                + "its momentum) | pymunk < emini |"), md);
    }

    @Test
    void trajectoriesAreComparedOnlyWhenTheSceneIsNotChaotic() {
        Trace engine = trace(t -> 10 * t, Map.of());
        Trace oracle = trace(t -> 10 * t + 3 * t, Map.of());
        Scenario calm = Scenes.valid("calm.yaml", ISOLATED.replace(
                "metrics: [linearMomentum, penetration]", "metrics: []"));
        Comparison.Row x = row(Comparison.compare(calm, "pass", engine, OK, oracle, null), "body.ball.x");
        assertEquals("series", x.figure());
        assertEquals(3, x.difference(), 1e-9);  // the largest |engine − oracle|, at t = 1
        assertEquals(Agreement.DIFFER, x.agreement());  // 1 px by default
        Scenario chaotic = Scenes.valid("chaos.yaml", ISOLATED.replace("metrics: [linearMomentum, penetration]",
                "metrics: []") + "\nreference: {oracle: {chaotic: true, tolerances: {\"body.*.x\": 5}}}");
        assertTrue(Comparison.compare(chaotic, "pass", engine, OK, oracle, null).rows().isEmpty());
        Scenario tolerant = Scenes.valid("tol.yaml", ISOLATED.replace("metrics: [linearMomentum, penetration]",
                "metrics: []") + "\nreference: {oracle: {tolerances: {\"body.*.x\": 5}}}");
        assertEquals(Agreement.AGREE, row(Comparison.compare(tolerant, "pass", engine, OK, oracle, null), "body.ball.x").agreement());
    }

    @Test
    void closedFormRowsUseTheScenesOwnErrorFigureAndSayWhichSideIsCloser() {
        Scenario s = Scenes.valid("cf.yaml",
                "world: {gravity: [0, 0]}",
                "bodies: [{name: ball, shape: {type: circle, radius: 5}, velocity: [10, 0]}]",
                "reference: {closedForm: {model: projectile, body: ball}}",
                "run:",
                "  duration: 1",
                "  record: {every: 0.1}",
                "  expect: [{closedForm: body.ball.x, of: finalError, atMost: 1}]");
        ClosedForm truth = (channel, t) -> channel.equals("body.ball.x") ? 10 * t : Double.NaN;
        // The engine is off by 2 px in the middle and exact at the end; the oracle off by 0.5 px at the end.
        Trace engine = trace(t -> 10 * t + (Math.abs(t - 0.5) < 1e-9 ? 2 : 0), Map.of());
        Trace oracle = trace(t -> 10 * t + (t > 0.95 ? 0.5 : 0), Map.of());
        Comparison.Row x = row(Comparison.compare(s, "pass", engine, OK, oracle, truth), "body.ball.x");
        assertEquals("series, finalError", x.figure());
        assertEquals(0, x.engineError(), 1e-9);
        assertEquals(0.5, x.oracleError(), 1e-9);
        assertEquals(Closer.ENGINE, x.closer());
        assertEquals(10, x.reference(), 1e-9);
        assertEquals("closed form projectile", x.referenceSource());
    }

    @Test
    void closerCallsTiesWithinNoiseOrFivePercent() {
        assertEquals(Closer.TIE, Comparison.closer(1e-12, 3e-12, 100));
        assertEquals(Closer.TIE, Comparison.closer(1.0, 1.04, 100));
        assertEquals(Closer.ENGINE, Comparison.closer(1.0, 1.2, 100));
        assertEquals(Closer.ORACLE, Comparison.closer(Double.NaN, 1.0, 100));
    }

    @Test
    void continuousCollisionScenesAreJudgedAgainstTheTruthOnly() {
        Scenario s = Scenes.valid("ccd.yaml",
                "world: {gravity: [0, 0]}",
                "bodies: [{name: wall, shape: {type: rectangle, width: 4, height: 100}, static: true},",
                "         {name: ball, shape: {type: circle, radius: 2}, position: [-50, 0], velocity: [1000, 0]}]",
                "reference: {oracle: {continuousCollision: true, chaotic: true}}",
                "run: {duration: 1, record: {every: 0.1, bodies: [ball], metrics: [{tunnelling: {walls: [wall]}}]}}");
        Trace engine = trace(t -> 0, Map.of("tunnelling.count", t -> 0));
        Trace oracle = trace(t -> 0, Map.of("tunnelling.count", t -> t > 0.15 ? 1 : 0));
        Comparison.Scene c = Comparison.compare(s, "pass", engine, OK, oracle, null);
        Comparison.Row tunnel = row(c, "tunnelling.count");
        assertEquals(Agreement.NOT_JUDGED, tunnel.agreement());
        assertEquals(Closer.ENGINE, tunnel.closer());
        assertTrue(c.note().contains("continuous collision"));
    }

    @Test
    void aMissingSideLeavesOnlyTheOtherAgainstTheTruthAndMisalignedTracesAreAnError() {
        Scenario s = Scenes.valid("iso.yaml", ISOLATED);
        Map<String, DoubleUnaryOperator> m = Map.of("momentum.x", t -> 10, "momentum.y", t -> 0,
                "penetration.max", t -> 0, "penetration.mean", t -> 0, "penetration.points", t -> 0);
        Comparison.Scene onlyOracle = Comparison.compare(s, "unsupported: joints", null, OK, trace(t -> t, m), null);
        assertEquals(CompareStatus.ORACLE_ONLY, onlyOracle.status());
        assertFalse(onlyOracle.rows().isEmpty());
        for (Comparison.Row r : onlyOracle.rows()) {
            assertEquals(Agreement.NONE, r.agreement());
            assertEquals(Closer.NONE, r.closer());
        }
        Trace shorter = new Trace(0.1, List.of("ball"), List.copyOf(m.keySet()));
        shorter.add(0, new double[6 + m.size()]);
        Comparison.Scene bad = Comparison.compare(s, "pass", trace(t -> t, m), OK, shorter, null);
        assertEquals(CompareStatus.ERROR, bad.status());
        assertTrue(bad.note().contains("11 samples against 1"));
    }

    @Test
    void anOracleRunThatLeftOutSomethingThatMovesBodiesIsNotJudged() {
        Scenario s = Scenes.valid("iso.yaml", ISOLATED);
        OracleScene incomplete = new OracleScene("f", "s", "ok", "", List.of(new OracleScene.Note("linear motor",
                "$.motors[0]", "left out", true)), List.of(), "t");
        Map<String, DoubleUnaryOperator> m = Map.of("momentum.x", t -> 10, "momentum.y", t -> 0,
                "penetration.max", t -> 0, "penetration.mean", t -> 0, "penetration.points", t -> 0);
        Comparison.Scene c = Comparison.compare(s, "pass", trace(t -> t, m), incomplete, trace(t -> t, m), null);
        for (Comparison.Row r : c.rows()) {
            assertEquals(Agreement.NOT_JUDGED, r.agreement());
            assertEquals(Closer.NONE, r.closer());
        }
        assertTrue(c.note().contains("linear motor (changes the motion)"));
    }

    @Test
    void traceFilesReadBackAsWritten(@TempDir Path dir) throws Exception {
        Trace t = trace(t1 -> 10 * t1, Map.of("energy.total", t1 -> t1 > 0.5 ? Double.NaN : 1));
        Path f = dir.resolve("a.trace.json");
        org.emini.harness.report.TraceWriter.write(f, "a", "emini", t);
        TraceReader.Read r = TraceReader.read(f);
        assertEquals("a", r.scene());
        assertEquals("emini", r.source());
        assertEquals(t.size(), r.trace().size());
        assertEquals(List.of("ball"), r.trace().bodies());
        assertEquals(10 * 0.3, r.trace().column("body.ball.x")[3], 1e-6);
        assertTrue(Double.isNaN(r.trace().column("energy.total")[10]));
        Files.writeString(f, Files.readString(f).replace("\"version\":1", "\"version\":2"));
        org.junit.jupiter.api.Assertions.assertThrows(java.io.IOException.class, () -> TraceReader.read(f));
    }

    @Test
    void oracleSettingsReadToleranceNamesAndGlobs() {
        Scenario s = Scenes.valid("set.yaml", ISOLATED
                + "\nreference: {oracle: {window: [0.2, 0.8], tolerances: {energy.total: 5, \"body.*.y\": 2}}}");
        OracleSettings o = OracleSettings.of(s.oracle());
        assertEquals(5, o.tolerance("energy.total"));
        assertEquals(2, o.tolerance("body.box[3].y"));
        assertTrue(Double.isNaN(o.tolerance("body.box[3].x")));
        assertTrue(o.inWindow(0.2) && o.inWindow(0.8) && !o.inWindow(0.9));
    }

    @Test
    void numbersInTheSummaryHaveFourSignificantDigits() {
        assertEquals("1.5", CompareReport.fmt(1.5));
        assertEquals("0.001234", CompareReport.fmt(0.0012341));
        assertEquals("1.235e-05", CompareReport.fmt(1.2345e-5));
        assertEquals("-", CompareReport.fmt(Double.NaN));
        assertEquals("12350", CompareReport.fmt(12345.6));
    }

    @Test
    void oracleResultsAreReadPerSceneFile(@TempDir Path dir) throws Exception {
        Path results = dir.resolve("oracle-results.json");
        Files.writeString(results, "{\"format\": \"emini-oracle-results\", \"version\": 1, \"scenes\": ["
                + "{\"file\": \"/s/a.yaml\", \"scene\": \"a\", \"status\": \"ok\", \"message\": \"\","
                + " \"unsupported\": [{\"element\": \"particles\", \"path\": \"$.particles\", \"reason\": \"r\","
                + " \"affectsBodies\": false}], \"approximations\": [], \"trace\": \"/t/a.trace.json\"},"
                + "{\"file\": \"/s/b.yaml\", \"scene\": \"b\", \"status\": \"skipped\", \"message\": \"why\","
                + " \"unsupported\": [], \"approximations\": [], \"trace\": null}]}");
        Map<Path, OracleScene> read = OracleRunner.read(results);
        OracleScene a = read.get(Path.of("/s/a.yaml"));
        assertTrue(a.ok());
        assertFalse(a.incomplete());
        assertEquals("particles", a.unsupported().get(0).element());
        OracleScene b = read.get(Path.of("/s/b.yaml"));
        assertFalse(b.ok());
        assertEquals("why", b.message());
    }
}
