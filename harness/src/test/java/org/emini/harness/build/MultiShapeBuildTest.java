package org.emini.harness.build;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.emini.dynamics.Body;
import org.emini.harness.Scenes;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.junit.jupiter.api.Test;

/** Multi-shapes: parts placed by offset and angle, nested ones composed, each with its own mass. */
class MultiShapeBuildTest {
    @Test
    void partsArePlacedTurnedAndWeighed() throws Exception {
        Body b = WorldBuilder.build(Scenes.valid("multi.yaml",
            "shapes:",
            "  bar: {type: rectangle, width: 20, height: 4, mass: 3}",
            "  hammer:",
            "    type: multiShape",
            "    friction: 0.5",
            "    parts:",
            "      - {shape: bar, offset: [10, 0], angle: 1.5707963267948966}",
            "      - {shape: {type: circle, radius: 2, mass: 1}, offset: [0, 5]}",
            "      - shape: {type: multiShape, parts: [{shape: bar, offset: [0, 10]}]}",
            "        offset: [-30, 0]",
            "        angle: 1.5707963267948966",
            "bodies:",
            "  - {name: hammer, shape: hammer}",
            "run: {duration: 0.1}")).body("hammer");
        MultiShape m = (MultiShape) b.getShape();
        assertEquals(3, m.getShapeCount());
        assertEquals(7, b.getMass(), 1e-5);
        assertEquals(0.5f, m.getFriction());
        // The bar turned a quarter: 4 wide, 20 high, centred at (10, 0).
        Polygon turned = (Polygon) m.getShape(0);
        float minX = Float.MAX_VALUE, maxX = -Float.MAX_VALUE, minY = Float.MAX_VALUE, maxY = -Float.MAX_VALUE;
        for (int i = 0; i < turned.getVertexCount(); i++) {
            minX = Math.min(minX, turned.getVertexX(i));
            maxX = Math.max(maxX, turned.getVertexX(i));
            minY = Math.min(minY, turned.getVertexY(i));
            maxY = Math.max(maxY, turned.getVertexY(i));
        }
        assertEquals(8, minX, 1e-4);
        assertEquals(12, maxX, 1e-4);
        assertEquals(-10, minY, 1e-4);
        assertEquals(10, maxY, 1e-4);
        Circle c = (Circle) m.getShape(1);
        assertEquals(0, c.getCenterX());
        assertEquals(5, c.getCenterY());
        // The nested bar: offset (0, 10) turned by a quarter is (-10, 0), then moved by (-30, 0).
        Polygon nested = (Polygon) m.getShape(2);
        assertEquals(-40, nested.getCentroidX(), 1e-4);
        assertEquals(0, nested.getCentroidY(), 1e-4);
        assertEquals(3, nested.getMass(), 1e-6);
    }
}
