package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Body;
import org.emini.harness.Scenes;
import org.emini.harness.load.Problem;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The scene format's kinematic bodies and Box2D filter fields reach the engine, and motion given to a
 * static body (which the engine refuses) is refused where the scene writes it.
 */
class KinematicAndFilterBuildTest {

    @Test
    void kinematicBodiesAndFiltersAreBuilt() throws Exception {
        BuiltWorld w = WorldBuilder.build(Scenes.valid("kinematic.yaml",
            "bodies:",
            "  - {name: lift, shape: {type: rectangle, width: 100, height: 10}, kinematic: true,"
                + " velocity: [0, -20], angularVelocity: 0.5}",
            "  - {name: box, shape: {type: circle, radius: 5}, categories: [1, 4], mask: [0, 31], group: -3}",
            "  - {name: plain, shape: {type: circle, radius: 5}}",
            "run: {duration: 0.1}"));
        Body lift = w.body("lift");
        assertTrue(lift.isKinematic());
        assertEquals(-20f, lift.getVelocityY());
        assertEquals(0.5f, lift.getAngularVelocity());
        Body box = w.body("box");
        assertTrue(box.isDynamic());
        assertEquals((1 << 1) | (1 << 4), box.getCategoryBits());
        assertEquals(1 | (1 << 31), box.getMaskBits());
        assertEquals(-3, box.getGroupIndex());
        Body plain = w.body("plain");
        assertTrue(plain.isDynamic());
        assertEquals(Body.DEFAULT_CATEGORY_BITS, plain.getCategoryBits());
        assertEquals(Body.DEFAULT_MASK_BITS, plain.getMaskBits());
        assertEquals(0, plain.getGroupIndex());
    }

    /** Motion on a static body, or both kinds at once: refused at the key that asks for it. */
    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "velocity: [3, 0]            | $.bodies[0].velocity        | kinematic: true",
        "angularVelocity: 1          | $.bodies[0].angularVelocity | kinematic: true",
        "kinematic: true             | $.bodies[0].kinematic       | not both",
    })
    void aStaticBodyIsRefusedMotionAndTheKinematicKind(String field, String path, String says) {
        Problem p = Scenes.onlyProblem(Scenes.load("wall.yaml",
            "bodies:",
            "  - {name: wall, shape: {type: circle, radius: 5}, static: true, " + field + "}",
            "run: {duration: 1}"));
        assertEquals(path, p.path());
        assertTrue(p.message().contains(says), p.message());
    }

    @Test
    void aVelocityActionOnAStaticBodyIsRefusedAtTheAction() {
        Problem p = Scenes.onlyProblem(Scenes.load("push-wall.yaml",
            "bodies:",
            "  - {name: wall, shape: {type: circle, radius: 5}, static: true}",
            "actions:",
            "  - {at: 0.5, type: velocity, body: wall, velocity: [10, 0]}",
            "run: {duration: 1}"));
        assertEquals("$.actions[0]", p.path());
        assertTrue(p.message().contains("static"), p.message());
    }

    @Test
    void aZeroVelocityActionOnAStaticBodyIsAccepted() {
        Scenes.valid("still-wall.yaml",
            "bodies:",
            "  - {name: wall, shape: {type: circle, radius: 5}, static: true}",
            "actions:",
            "  - {at: 0.5, type: velocity, body: wall, velocity: [0, 0], angularVelocity: 0}",
            "run: {duration: 1}");
    }
}
