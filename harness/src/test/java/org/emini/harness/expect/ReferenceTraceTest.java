package org.emini.harness.expect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.emini.harness.Repo;
import org.emini.harness.Scenes;
import org.emini.harness.load.Problem;
import org.emini.harness.load.ScenarioFiles;
import org.emini.harness.load.ScenarioLoader;
import org.emini.harness.report.TraceWriter;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.Status;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.SceneScaling;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A run compared with a stored reference trace ({@code minus: {trace: FILE}}): the difference is reduced
 * and bounded like any channel's, and a reference that is missing, lacks the channel or is sampled
 * differently is a located problem naming the file and the channel.
 */
class ReferenceTraceTest {
    /** A ball falling freely for 2 s at 60 ticks/s under g (px/s²), recorded every 0.05 s. */
    private static String drop(double g, String every, String... expect) {
        return String.join("\n",
                "world: {ticksPerSecond: 60, gravity: [0, " + g + "]}",
                "bodies: [{name: ball, shape: {type: circle, radius: 5}}]",
                "run:",
                "  duration: 2",
                "  record: {every: " + every + ", bodies: [ball]}",
                "  expect:",
                String.join("\n", expect));
    }

    /** Writes the scene text to {@code dir/name} and loads it from there (the reference is relative to it). */
    private static ScenarioLoader.Loaded load(Path dir, String name, String text) throws Exception {
        Path file = dir.resolve(name);
        Files.writeString(file, text);
        return Scenes.loader().load(file);
    }

    /** The reference: the same drop under g = 100, run and written as `harness run` writes traces. */
    private static void reference(Path dir) throws Exception {
        Scenario ref = load(dir, "ref.yaml", drop(100, "0.05", "    - {stable: {}}")).scenario();
        SceneResult r = ScenarioRunner.run(ref, n -> { });
        TraceWriter.write(dir.resolve("traces/ref.trace.json"), "ref", "emini", r.trace());
    }

    private static final String AGAINST = "    - {metric: body.ball.y, minus: {trace: traces/ref.trace.json}, of: maxAbs, atMost: 0.01}";

    @Test
    void theSameRunMatchesItsReferenceAndAnotherGravityFailsByTheClosedFormDifference(@TempDir Path dir) throws Exception {
        reference(dir);
        ScenarioLoader.Loaded same = load(dir, "same.yaml", drop(100, "0.05", AGAINST));
        assertTrue(same.ok(), same.problems().toString());
        SceneResult r = ScenarioRunner.run(same.scenario(), n -> { });
        assertTrue(r.verdicts().get(0).passed(), r.verdicts().get(0).detail());
        // The same run: the trace prints body values as the shortest text of their float, read back as a double.
        assertEquals(0, r.verdicts().get(0).measured(), Math.ulp(210f), "the same run, up to the float's printing");
        // Under g = 110 the ball is ahead by (110 − 100) t² / 2 = 20 px at 2 s (the integrator's own error
        // is the same fraction of both runs): the comparison fails and says against what.
        SceneResult other = ScenarioRunner.run(load(dir, "other.yaml", drop(110, "0.05", AGAINST)).scenario(), n -> { });
        assertFalse(other.verdicts().get(0).passed());
        assertEquals(20, other.verdicts().get(0).measured(), 0.5);
        assertTrue(other.verdicts().get(0).detail().contains("minus body.ball.y of the reference trace traces/ref.trace.json"),
                other.verdicts().get(0).detail());
        // Another channel of the reference: the ball's y against its own x (0 throughout) is just y.
        SceneResult x = ScenarioRunner.run(load(dir, "x.yaml", drop(100, "0.05",
                "    - {metric: body.ball.y, minus: {trace: traces/ref.trace.json, channel: body.ball.x}, of: final, near: 200, tolerance: 5}"))
                .scenario(), n -> { });
        assertTrue(x.verdicts().get(0).passed(), x.verdicts().get(0).detail());
    }

    @Test
    void theLibrarysReferenceScenePassesAndFailsWhenItsRunDiffers(@TempDir Path dir) throws Exception {
        Path scene = Repo.scenarios().resolve("joints/double-pendulum-reference.yaml");
        SceneResult r = ScenarioRunner.run(Scenes.loader().load(scene).scenario(), n -> { });
        assertEquals(Status.PASS, r.status(), r.message() + " " + r.verdicts());
        // The same scene under 20% more gravity swings faster: tens of px from pymunk's stored run.
        Files.copy(scene.resolveSibling("double-pendulum-reference.pymunk.trace.json"),
                dir.resolve("double-pendulum-reference.pymunk.trace.json"));
        String text = Files.readString(scene).replace("world: {ticksPerSecond: 60}", "world: {ticksPerSecond: 60, gravity: [0, 120]}");
        ScenarioLoader.Loaded heavier = load(dir, "double-pendulum-reference.yaml", text);
        assertTrue(heavier.ok(), heavier.problems().toString());
        SceneResult f = ScenarioRunner.run(heavier.scenario(), n -> { });
        assertEquals(Status.FAIL, f.status());
        assertFalse(f.verdicts().get(0).passed());
        assertTrue(f.verdicts().get(0).measured() > 10, f.verdicts().get(0).detail());
        assertTrue(f.verdicts().get(3).passed(), "the arms still hold: only the comparison fails");
    }

    @Test
    void aScaledRunScalesItsReference(@TempDir Path dir) throws Exception {
        reference(dir);
        Scenario s = load(dir, "same.yaml", drop(100, "0.05", AGAINST)).scenario();
        SceneResult r = ScenarioRunner.run(SceneScaling.scale(s, 32), n -> { });
        // Times 32 (a power of two) the run is the reference's times 32 bit for bit (up to the float's printing,
        // times 32); compared with the reference unscaled it would be 31 times 200 px off.
        assertTrue(r.verdicts().get(0).passed(), r.verdicts().get(0).detail());
        assertEquals(0, r.verdicts().get(0).measured(), 32 * Math.ulp(210f));
    }

    @Test
    void aMissingFileAChannelItLacksAndOtherSamplingAreLocatedProblems(@TempDir Path dir) throws Exception {
        reference(dir);
        Problem missing = Scenes.onlyProblem(load(dir, "m.yaml", drop(100, "0.05",
                "    - {metric: body.ball.y, minus: {trace: traces/nothing.trace.json}, of: maxAbs, atMost: 1}")));
        assertEquals("$.run.expect[0].minus.trace", missing.path());
        assertTrue(missing.message().startsWith("the reference trace traces/nothing.trace.json (")
                && missing.message().endsWith(") does not exist"), missing.message());
        Problem lacks = Scenes.onlyProblem(load(dir, "c.yaml", drop(100, "0.05",
                "    - {metric: body.ball.y, minus: {trace: traces/ref.trace.json, channel: energy.total}, of: maxAbs, atMost: 1}")));
        assertEquals("$.run.expect[0].minus.channel", lacks.path());
        assertTrue(lacks.message().startsWith("the reference trace traces/ref.trace.json has no channel energy.total (it has body.ball.x"),
                lacks.message());
        Problem sampling = Scenes.onlyProblem(load(dir, "s.yaml", drop(100, "0.1", AGAINST)));
        assertEquals("$.run.expect[0].minus.trace", sampling.path());
        assertEquals("the reference trace traces/ref.trace.json has 41 samples (last tick 120), this run 21 (last tick 120): "
                + "run.duration and run.record.every must be the reference's", sampling.message());
        Files.writeString(dir.resolve("traces/broken.trace.json"), "{\"format\": \"emini-trace\", \"version\": 1, \"tick\": 3}");
        Problem broken = Scenes.onlyProblem(load(dir, "b.yaml", drop(100, "0.05",
                "    - {metric: body.ball.y, minus: {trace: traces/broken.trace.json}, of: maxAbs, atMost: 1}")));
        assertTrue(broken.message().contains("is not an emini-trace"), broken.message());
        Problem nul = Scenes.onlyProblem(load(dir, "n.yaml", drop(100, "0.05",
                "    - {metric: body.ball.y, minus: {trace: \"a\\0b\"}, of: maxAbs, atMost: 1}")));
        assertTrue(nul.message().contains("is not a file name"), nul.message());
        Problem group = Scenes.onlyProblem(load(dir, "g.yaml", drop(100, "0.05",
                "    - {metric: 'body.b*.y', minus: {trace: traces/ref.trace.json}, of: maxAbs, atMost: 1}")));
        assertEquals("minus: {trace} takes one body's channel, not a group", group.message());
        assertNotNull(load(dir, "ok.yaml", drop(100, "0.05", AGAINST)).scenario());
        // A folder run does not take the stored traces for scenes.
        assertFalse(ScenarioFiles.isScene(dir.resolve("traces/ref.trace.json")));
        assertTrue(ScenarioFiles.isScene(dir.resolve("ref.json")));
    }
}
