package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.List;

/**
 * A shape: circle (maybe off-centre), rectangle, regular polygon, convex polygon (around the origin
 * or off it) or multi-shape (parts placed as a scene places them), optionally moved to its centroid
 * with the engine's {@code centred()}, and its material.
 */
public final class ShapeRecipe {
    /** Shape kinds (the scene's names). */
    public enum Kind { circle, rectangle, regularPolygon, polygon, multiShape }

    /** A multi-shape part: its shape turned by angle, then moved by the offset. */
    public static final class Part {
        /** The part (not itself a multi-shape). */
        public ShapeRecipe shape;
        /** Offset (px). */
        public float offsetX;
        /** Offset (px). */
        public float offsetY;
        /** Rotation (rad). */
        public float angle;
    }

    /** Id as generated. */
    public int id;
    /** The kind. */
    public Kind kind = Kind.circle;
    /** Circle and regular polygon radius (px). */
    public float radius;
    /** Rectangle size (px). */
    public float width;
    /** Rectangle size (px). */
    public float height;
    /** Regular polygon sides. */
    public int sides;
    /** An off-centre circle's centre in the shape frame (px). */
    public float centerX;
    /** An off-centre circle's centre. */
    public float centerY;
    /** Polygon vertices x0, y0, x1, ... (px). */
    public float[] vertices;
    /** Multi-shape parts. */
    public List<Part> parts = new ArrayList<>();
    /** Call the engine's {@code centred()} on the polygon or multi-shape. */
    public boolean centred;
    /** Mass. */
    public float mass = 1f;
    /** Friction factor. */
    public float friction = 0.25f;
    /** Elasticity factor. */
    public float elasticity;

    /** Whether it is a circle whose centre is off the origin (a scene cannot say that). */
    public boolean offCentreCircle() {
        return kind == Kind.circle && (centerX != 0f || centerY != 0f);
    }
}
