package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.emini.dynamics.Landscape;
import org.emini.world.World;
import org.emini.harness.Scenes;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.junit.jupiter.api.Test;

/** The landscape, the simulation area and multi-shapes through the engine's public API. */
class ElementBuildersTest {
    @Test
    void landscapeMaterialSegmentsAndFaces() throws Exception {
        World w = WorldBuilder.build(Scenes.valid("l.yaml",
                "landscape:",
                "  friction: 0.5",
                "  elasticity: 0.2",
                "  segments:",
                "    - {from: [0, 0], to: [100, 0], face: left}",
                "    - {name: back, from: [100, 0], to: [0, -50], face: left}",
                "    - {from: [0, 10], to: [10, 10]}",
                "run: {duration: 1}")).world();
        Landscape l = w.getLandscape();
        assertEquals(0.5f, l.getFriction());
        assertEquals(0.2f, l.getElasticity());
        assertEquals(3, l.getSegmentCount());
        assertEquals(Landscape.FACE_LEFT, l.getFace(0));
        // Given right to left, the engine stores it left to right with the face flipped: same solid side.
        assertEquals(0f, l.getStartX(1));
        assertEquals(Landscape.FACE_RIGHT, l.getFace(1));
        assertEquals(Landscape.FACE_NONE, l.getFace(2));
    }

    @Test
    void landscapeDefaultsAreTheManuals() throws Exception {
        Landscape l = WorldBuilder.build(Scenes.valid("d.yaml", "landscape: {segments: [{from: [0, 0], to: [1, 0]}]}",
                "run: {duration: 1}")).world().getLandscape();
        assertEquals(0.25f, l.getFriction());
        assertEquals(0f, l.getElasticity());
    }

    @Test
    void simulationAreaIsTheXRange() throws Exception {
        World w = WorldBuilder.build(Scenes.valid("a.yaml", "world: {simulationArea: {start: -10, end: 30}}",
                "run: {duration: 1}")).world();
        assertTrue(w.hasSimulationArea());
        assertEquals(-10f, w.getSimulationAreaMinX());
        assertEquals(30f, w.getSimulationAreaMaxX());
        assertEquals(-Float.MAX_VALUE, w.getSimulationAreaMinY());
        assertTrue(Scenes.load("b.yaml", "world: {simulationArea: {start: 10, end: -30}}", "run: {duration: 1}")
                .problems().toString().contains("the simulation area ends before it starts"));
    }

    @Test
    void simulationAreaMayBeARectangle() throws Exception {
        World w = WorldBuilder.build(Scenes.valid("r.yaml", "world: {simulationArea: {min: [-10, -20], max: [30, 40]}}",
                "run: {duration: 1}")).world();
        assertEquals(-10f, w.getSimulationAreaMinX());
        assertEquals(-20f, w.getSimulationAreaMinY());
        assertEquals(30f, w.getSimulationAreaMaxX());
        assertEquals(40f, w.getSimulationAreaMaxY());
        assertTrue(Scenes.load("s.yaml", "world: {simulationArea: {min: [0, 0], max: [30, -1]}}", "run: {duration: 1}")
                .problems().toString().contains("max is below its min"));
        assertTrue(!Scenes.load("t.yaml", "world: {simulationArea: {start: 0, end: 1, min: [0, 0], max: [1, 1]}}",
                "run: {duration: 1}").ok(), "one form or the other");
        assertTrue(!Scenes.load("u.yaml", "world: {simulationArea: {start: 0, max: [1, 1]}}",
                "run: {duration: 1}").ok(), "not half of each");
    }

    @Test
    void multiShapePartsArePlacedByOffsetAndAngleWithTheirMasses() throws Exception {
        BuiltWorld w = WorldBuilder.build(Scenes.valid("m.yaml",
                "shapes:",
                "  bar: {type: rectangle, width: 40, height: 6, mass: 3}",
                "  knob: {type: circle, radius: 5}",
                "  inner: {type: multiShape, mass: 4, parts: [{shape: knob, offset: [0, 10]}, {shape: knob}]}",
                "  hammer:",
                "    type: multiShape",
                "    friction: 0.7",
                "    parts:",
                "      - {shape: bar, angle: 1.5707963267948966}",
                "      - {shape: inner, offset: [20, 0], angle: 1.5707963267948966}",
                "bodies: [{name: h, shape: hammer}]",
                "run: {duration: 1}"));
        MultiShape m = (MultiShape) w.body("h").getShape();
        assertEquals(3, m.getShapeCount());
        assertEquals(7f, m.getMass(), 1e-5f);            // 3 + 4: the nested multi-shape weighs its own mass
        assertEquals(0.7f, m.getFriction());
        Polygon bar = (Polygon) m.getShape(0);            // turned a quarter: 6 wide, 40 high
        float minX = Float.MAX_VALUE;
        float maxY = -Float.MAX_VALUE;
        for (int i = 0; i < bar.getVertexCount(); i++) {
            minX = Math.min(minX, bar.getVertexX(i));
            maxY = Math.max(maxY, bar.getVertexY(i));
        }
        assertEquals(-3f, minX, 1e-4f);
        assertEquals(20f, maxY, 1e-4f);
        Circle knob = (Circle) m.getShape(1);             // (0, 10) turned a quarter is (−10, 0), then + (20, 0)
        assertEquals(10f, knob.getCenterX(), 1e-4f);
        assertEquals(0f, knob.getCenterY(), 1e-4f);
        assertEquals(2f, knob.getMass(), 1e-5f);          // each knob: 1 of 2, scaled to the inner 4
        assertEquals(20f, ((Circle) m.getShape(2)).getCenterX(), 1e-4f);
    }
}
