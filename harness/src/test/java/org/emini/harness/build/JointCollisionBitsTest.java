package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
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
 * Joints with {@code collide: false} keep their two bodies apart without stopping any other pair
 * colliding (issue 14: bits were 31 − (i mod 32), so joint 32 shared joint 0's bit and the scene's own
 * layers, and unrelated bodies fell through each other).
 */
class JointCollisionBitsTest {

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
    void jointBitsAvoidTheScenesOwnLayers() throws Exception {
        BuiltWorld w = WorldBuilder.build(Scenes.valid("layers.yaml",
                "shapes: {b: {type: circle, radius: 5}}",
                "bodies:",
                "  - {name: p, shape: b, position: [0, 0], layers: [31]}",
                "  - {name: q, shape: b, position: [100, 0], layers: [31]}",
                "  - {name: a, shape: b, position: [200, 0]}",
                "  - {name: c, shape: b, position: [210, 0]}",
                "joints: [{bodyA: a, bodyB: c, at: [205, 0]}]",
                "run: {duration: 1}"));
        int a = w.body("a").getCollisionLayers();
        assertEquals(a, w.body("c").getCollisionLayers());
        assertTrue(a != 0, "the jointed pair shares a bit");
        assertEquals(0, a & w.body("p").getCollisionLayers(), "and it is not the scene's layer 31");
    }

    /** A chain's links share no bit unless both of them are kept apart from every member of it. */
    @Test
    void onlyPairsThatMayNotCollideShareABit() throws Exception {
        BuiltWorld w = WorldBuilder.build(Scenes.valid("chain.yaml",
                "shapes: {b: {type: circle, radius: 5}}",
                "bodies:",
                "  - {name: l0, shape: b, position: [0, 0]}",
                "  - {name: l1, shape: b, position: [10, 0]}",
                "  - {name: l2, shape: b, position: [20, 0]}",
                "  - {name: l3, shape: b, position: [30, 0]}",
                "  - {name: s, shape: b, position: [90, 0], static: true}",
                "  - {name: t, shape: b, position: [99, 0], static: true}",
                "joints:",
                "  - {bodyA: l0, bodyB: l1, at: [5, 0]}",
                "  - {bodyA: l1, bodyB: l2, at: [15, 0]}",
                "  - {bodyA: l2, bodyB: l3, at: [25, 0]}",
                "  - {bodyA: s, bodyB: t, at: [95, 0]}",
                "  - {bodyA: l0, bodyB: l2, at: [10, 0], collide: true}",
                "run: {duration: 1}"));
        List<String> names = List.of("l0", "l1", "l2", "l3", "s", "t");
        List<String> apart = List.of("l0-l1", "l1-l2", "l2-l3");
        for (int i = 0; i < names.size(); i++) {
            for (int j = i + 1; j < names.size(); j++) {
                Body a = w.body(names.get(i));
                Body b = w.body(names.get(j));
                boolean shared = (a.getCollisionLayers() & b.getCollisionLayers()) != 0;
                boolean mayCollide = a.isDynamic() || b.isDynamic();
                if (mayCollide) {
                    assertEquals(apart.contains(names.get(i) + "-" + names.get(j)), shared, names.get(i) + "-" + names.get(j));
                }
            }
        }
        assertEquals(0, w.body("s").getCollisionLayers(), "two static bodies need no bit");
    }

    /** 33 pendulums need 33 bits; the engine has 32: the scene is unsupported, naming joint 32. */
    @Test
    void moreNonCollidingPairsThanBitsIsUnsupportedAtTheFirstJointWithout() {
        List<String> lines = new ArrayList<>(List.of("shapes: {b: {type: circle, radius: 5}}", "bodies:"));
        List<String> joints = new ArrayList<>(List.of("joints:"));
        for (int i = 0; i <= 32; i++) {
            lines.add("  - {name: pivot" + i + ", shape: b, position: [" + 30 * i + ", 0], static: true}");
            lines.add("  - {name: bob" + i + ", shape: b, position: [" + 30 * i + ", 8]}");
            joints.add("  - {bodyA: pivot" + i + ", bodyB: bob" + i + ", at: [" + 30 * i + ", 0]}");
        }
        lines.addAll(joints);
        lines.add("run: {duration: 1}");
        var scene = Scenes.valid("pendulums.yaml", lines.toArray(new String[0]));
        UnsupportedElementException e = assertThrows(UnsupportedElementException.class, () -> WorldBuilder.build(scene));
        assertTrue(e.getMessage().contains("$.joints[32]"), e.getMessage());
        SceneResult r = ScenarioRunner.run(scene, n -> { });
        assertEquals(Status.UNSUPPORTED, r.status());
        assertTrue(r.message().contains("collide: false"), r.message());
    }
}
