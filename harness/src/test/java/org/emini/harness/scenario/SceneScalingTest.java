package org.emini.harness.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.emini.dynamics.Body;
import org.emini.harness.Repo;
import org.emini.harness.Scenes;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.build.WorldBuilder;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.Status;
import org.junit.jupiter.api.Test;

/**
 * {@code run --scale} (issue 17's length scale): a scene at k times its size, with the engine's length
 * scale times k, is the same physics. With k a power of two every float product and root scales
 * exactly, so the scaled world must follow the original bit for bit, times k: any length tolerance in
 * the engine that does not follow the length scale breaks that.
 */
class SceneScalingTest {
    private static Scenario library(String id) {
        return Scenes.loader().load(Repo.scenarios().resolve(id + ".yaml")).scenario();
    }

    private static void assertScaledRunIsTheSameTimesK(String id, float k, int ticks) throws Exception {
        Scenario original = library(id);
        BuiltWorld a = WorldBuilder.build(original);
        BuiltWorld b = WorldBuilder.build(SceneScaling.scale(original, k));
        for (int t = 0; t < ticks; t++) {
            a.world().tick();
            b.world().tick();
        }
        for (Map.Entry<String, Body> e : a.bodies().entrySet()) {
            Body x = e.getValue();
            Body y = b.body(e.getKey());
            String at = id + " ×" + k + ", " + e.getKey() + " after " + ticks + " ticks";
            assertEquals(x.getX() * k, y.getX(), 0f, at + ": x");
            assertEquals(x.getY() * k, y.getY(), 0f, at + ": y");
            assertEquals(x.getAngle(), y.getAngle(), 0f, at + ": angle");
            assertEquals(x.getVelocityX() * k, y.getVelocityX(), 0f, at + ": vx");
        }
    }

    @Test
    void aPyramidScaledByAPowerOfTwoIsTheSamePyramidBitForBit() throws Exception {
        assertScaledRunIsTheSameTimesK("stacking/pyramid-10-20hz", 32f, 100);
        assertScaledRunIsTheSameTimesK("stacking/pyramid-10-20hz", 1 / 32f, 100);
    }

    @Test
    void fastBodiesScaledByAPowerOfTwoAreTheSameBitForBit() throws Exception {
        assertScaledRunIsTheSameTimesK("fast-bodies/spinning-rod-hits-ball", 32f, 40);
        assertScaledRunIsTheSameTimesK("fast-bodies/bullet-vs-landscape", 1 / 8f, 10);
    }

    @Test
    void halfPixelBoxesStackOnlyWithTheScaledSetting() {
        Scenario tower = SceneScaling.scale(library("stacking/tower-10-20hz"), 0.025);
        assertEquals(0.025, tower.world().solver().get("lengthScale"), 1e-12);
        assertEquals(Status.PASS, ScenarioRunner.run(tower, n -> { }).status(), "0.5 px tower, scaled setting");
        Map<String, Double> unscaled = Map.of();
        Scenario without = new Scenario(tower.name(), tower.file(), tower.description(), tower.category(),
                new WorldSpec(tower.world().timestep(), tower.world().iterations(), tower.world().dynamicIterations(),
                        tower.world().gravityX(), tower.world().gravityY(), 0, 0, false, unscaled,
                        tower.world().sleeping()), tower.shapes(), tower.bodies(), tower.actions(), tower.elements(),
                tower.run(), tower.closedForm(), tower.oracle(), tower.knownFailure());
        SceneResult r = ScenarioRunner.run(without, n -> { });
        assertEquals(Status.FAIL, r.status(), "the same tower at the 20 px tolerances must fail its scaled bounds");
    }

    @Test
    void boundsScaleByTheirUnits() {
        Scenario s = Scenes.valid("s.yaml",
                "shapes: {ball: {type: circle, radius: 10}}",
                "bodies: [{name: ball, shape: ball, position: [0, 0], velocity: [3, 0]}]",
                "run:",
                "  duration: 1",
                "  expect:",
                "    - {metric: energy.total, of: maxDrift, atMost: 2}",
                "    - {metric: energy.total, of: maxDrift, relative: true, atMost: 0.01}",
                "    - {metric: penetration.max, of: max, atMost: 0.5}",
                "    - {body: ball, endsNear: [1, 2], tolerance: 3}",
                "    - {stable: {maxSpeed: 10, maxAngularSpeed: 1}}");
        List<ExpectationSpec> e = SceneScaling.scale(s, 4).run().expect();
        assertEquals(32, e.get(0).atMost(), 1e-12);
        assertEquals(0.01, e.get(1).atMost(), 1e-12);
        assertEquals(2, e.get(2).atMost(), 1e-12);
        assertEquals(4, e.get(3).point()[0], 1e-12);
        assertEquals(12, e.get(3).tolerance(), 1e-12);
        assertEquals(40, e.get(4).maxSpeed(), 1e-12);
        assertEquals(1, e.get(4).maxAngularSpeed(), 1e-12);
        assertEquals(40, SceneScaling.scale(s, 4).shapes().get("ball").radius(), 1e-12);
        assertEquals(400, SceneScaling.scale(s, 4).world().gravityY(), 1e-12);
    }

    @Test
    void everyChannelHasAUnit() {
        for (List<String> channels : Channels.OF_METRIC.values()) {
            for (String c : channels) {
                int p = SceneScaling.lengthPower(c);
                assertTrue(p >= 0 && p <= 2, c);
            }
        }
        for (String q : Channels.BODY_QUANTITIES) {
            SceneScaling.lengthPower(Channels.body("ball", q));
        }
    }

    @Test
    void scenesWithElementsItCannotScaleAreRefusedByName() {
        Scenario pendulum = library("closed-form/pendulum-90deg");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SceneScaling.scale(pendulum, 2));
        assertTrue(e.getMessage().contains("joints"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> SceneScaling.scale(pendulum, 0));
    }
}
