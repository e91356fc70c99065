package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.emini.dynamics.Body;
import org.emini.harness.Scenes;
import org.emini.harness.run.SceneResult;
import org.emini.harness.run.ScenarioRunner;
import org.emini.harness.run.Status;
import org.junit.jupiter.api.Test;

/**
 * Joints with {@code collide: false} keep exactly their two bodies apart, through the engine's pair
 * switch, without stopping any other pair colliding (issue 14: bits were 31 − (i mod 32), so joint 32
 * shared joint 0's bit and the scene's own layers, and unrelated bodies fell through each other).
 */
class ConnectedPairsTest {

    /**
     * 33 boxes, each jointed to a non-interacting handle (which needs no bit at all), box 32 dropped on
     * box 0. Before the fix box 32 and box 0 both had bit 31 and box 32 fell into box 0.
     */
    @Test
    void theBoxOnJoint32LandsOnTheBoxOnJoint0() {
        List<String> lines = new ArrayList<>(List.of(
                "shapes: {box: {type: rectangle, width: 20, height: 20}, handle: {type: circle, radius: 1, mass: 0.01}}",
                "bodies:",
                "  - {name: ground, shape: {type: rectangle, width: 2000, height: 20}, position: [0, 10], static: true}"));
        List<String> joints = new ArrayList<>(List.of("joints:"));
        for (int i = 0; i <= 32; i++) {
            double x = i == 32 ? 0 : i * 50;
            double y = i == 32 ? -60 : -10;
            lines.add("  - {name: box" + i + ", shape: box, position: [" + x + ", " + y + "]}");
            lines.add("  - {name: handle" + i + ", shape: handle, position: [" + x + ", " + y + "], interacting: false}");
            joints.add("  - {bodyA: box" + i + ", bodyB: handle" + i + ", at: [" + x + ", " + y + "]}");
        }
        lines.addAll(joints);
        lines.add("run:");
        lines.add("  duration: 3");
        lines.add("  expect:");
        lines.add("    - {metric: body.box32.y, of: final, atMost: -25, why: \"it rests on box 0, its centre 20 px above\"}");
        SceneResult r = ScenarioRunner.run(Scenes.valid("33.yaml", lines.toArray(new String[0])), n -> { });
        assertEquals(Status.PASS, r.status(), r.message() + " " + r.verdicts());
    }

    @Test
    void theScenesOwnLayersAreLeftAsTheyAre() throws Exception {
        BuiltWorld w = WorldBuilder.build(Scenes.valid("layers.yaml",
                "shapes: {b: {type: circle, radius: 5}}",
                "bodies:",
                "  - {name: p, shape: b, position: [0, 0], layers: [31]}",
                "  - {name: a, shape: b, position: [200, 0]}",
                "  - {name: c, shape: b, position: [210, 0]}",
                "joints: [{bodyA: a, bodyB: c, at: [205, 0]}]",
                "run: {duration: 1}"));
        assertEquals(0, w.body("a").getCollisionLayers());
        assertEquals(1 << 31, w.body("p").getCollisionLayers());
        assertTrue(w.world().isCollisionDisabled(w.body("a"), w.body("c")));
    }

    /** Only the jointed pairs of a chain are kept apart; links two apart, and collide: true joints, still collide. */
    @Test
    void onlyTheJointedPairsAreKeptApart() throws Exception {
        BuiltWorld w = WorldBuilder.build(Scenes.valid("chain.yaml",
                "shapes: {b: {type: circle, radius: 5}}",
                "bodies:",
                "  - {name: l0, shape: b, position: [0, 0]}",
                "  - {name: l1, shape: b, position: [10, 0]}",
                "  - {name: l2, shape: b, position: [20, 0]}",
                "  - {name: l3, shape: b, position: [30, 0]}",
                "joints:",
                "  - {bodyA: l0, bodyB: l1, at: [5, 0]}",
                "  - {bodyA: l1, bodyB: l2, at: [15, 0]}",
                "  - {bodyA: l2, bodyB: l3, at: [25, 0]}",
                "  - {bodyA: l0, bodyB: l2, at: [10, 0], collide: true}",
                "run: {duration: 1}"));
        List<String> names = List.of("l0", "l1", "l2", "l3");
        List<String> apart = List.of("l0-l1", "l1-l2", "l2-l3");
        for (int i = 0; i < names.size(); i++) {
            for (int j = i + 1; j < names.size(); j++) {
                Body a = w.body(names.get(i));
                Body b = w.body(names.get(j));
                String pair = names.get(i) + "-" + names.get(j);
                assertEquals(apart.contains(pair), w.world().isCollisionDisabled(a, b), pair);
            }
        }
    }

    /** 33 pendulums, each bob kept from its pivot: no limit of 32 any more. */
    @Test
    void aScenesNonCollidingPairsAreNotLimitedToTheLayerBits() throws Exception {
        List<String> lines = new ArrayList<>(List.of("shapes: {b: {type: circle, radius: 5}}", "bodies:"));
        List<String> joints = new ArrayList<>(List.of("joints:"));
        for (int i = 0; i <= 32; i++) {
            lines.add("  - {name: pivot" + i + ", shape: b, position: [" + 30 * i + ", 0], static: true}");
            lines.add("  - {name: bob" + i + ", shape: b, position: [" + 30 * i + ", 8]}");
            joints.add("  - {bodyA: pivot" + i + ", bodyB: bob" + i + ", at: [" + 30 * i + ", 0]}");
        }
        lines.addAll(joints);
        lines.add("run: {duration: 1}");
        BuiltWorld w = WorldBuilder.build(Scenes.valid("pendulums.yaml", lines.toArray(new String[0])));
        assertTrue(w.world().isCollisionDisabled(w.body("pivot32"), w.body("bob32")));
        assertEquals(0, w.body("bob32").getCollisionLayers());
    }
}
