package org.emini.harness.scenario;

import java.util.List;
import org.emini.harness.load.JsonPath;

/**
 * A shape as the scene describes it (not yet an engine shape).
 *
 * @param name the name under {@code shapes}, or null for a shape written in place
 * @param kind which factory builds it
 * @param radius circle and regular polygon radius (px)
 * @param width rectangle width (px)
 * @param height rectangle height (px)
 * @param sides regular polygon sides
 * @param vertices polygon vertices (px, around the shape origin)
 * @param parts multi-shape parts
 * @param mass mass (default 1)
 * @param friction friction factor (default 0.25)
 * @param elasticity elasticity factor (default 0)
 * @param path where the shape is written
 */
public record ShapeSpec(String name, Kind kind, double radius, double width, double height, int sides,
                        List<double[]> vertices, List<Part> parts, double mass, double friction,
                        double elasticity, JsonPath path) {

    /** Shape kinds, named as in the scene files. */
    public enum Kind { circle, rectangle, regularPolygon, polygon, multiShape }

    /**
     * A part of a multi-shape.
     *
     * @param shape the part's shape
     * @param offsetX offset of the part's origin (px)
     * @param offsetY offset of the part's origin (px)
     * @param angle the part's rotation (rad)
     */
    public record Part(ShapeSpec shape, double offsetX, double offsetY, double angle) {
    }

    /**
     * Width and height of the shape's bounding box at angle 0, used for default generator spacing.
     * Regular polygons use their circumscribed circle (the engine decides where the vertices fall).
     */
    public double[] size() {
        switch (kind) {
            case circle:
            case regularPolygon:
                return new double[] {2 * radius, 2 * radius};
            case rectangle:
                return new double[] {width, height};
            case polygon: {
                double minX = Double.MAX_VALUE, minY = Double.MAX_VALUE;
                double maxX = -Double.MAX_VALUE, maxY = -Double.MAX_VALUE;
                for (double[] v : vertices) {
                    minX = Math.min(minX, v[0]);
                    maxX = Math.max(maxX, v[0]);
                    minY = Math.min(minY, v[1]);
                    maxY = Math.max(maxY, v[1]);
                }
                return new double[] {maxX - minX, maxY - minY};
            }
            default:
                return null;
        }
    }
}
