package org.emini.harness.fuzz.world;

import org.emini.dynamics.Landscape;
import org.emini.event.Event;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/** Whole-world changes for the metamorphic relations: moving and mirroring a recipe in place. */
public final class Transforms {
    private Transforms() {
    }

    /** Moves every position (bodies, world pivots, world emitters, segments, area, position events). */
    public static void translate(Recipe r, float dx, float dy) {
        for (BodyRecipe b : r.bodies) {
            b.x += dx;
            b.y += dy;
        }
        for (JointRecipe j : r.joints) {
            j.x += dx;
            j.y += dy;
        }
        for (EmitterRecipe e : r.emitters) {
            if (e.body < 0) {
                e.x1 += dx;
                e.x2 += dx;
                e.y1 += dy;
                e.y2 += dy;
            }
        }
        for (SegmentRecipe s : r.segments) {
            s.x1 += dx;
            s.x2 += dx;
            s.y1 += dy;
            s.y2 += dy;
        }
        if (r.area != null) {
            r.area.minX += dx;
            r.area.maxX += dx;
            r.area.minY += dy;
            r.area.maxY += dy;
        }
        for (EventRecipe e : r.events) {
            if (e.type == Event.POSITION) {
                e.p1 += dx;
                e.p3 += dx;
                e.p2 += dy;
                e.p4 += dy;
            }
        }
    }

    /**
     * Mirrors the world in x → −x: positions, velocities, gravity and local anchors negate their x,
     * angles and angular velocities (and rotational motor targets, torques) their sign; shapes are
     * mirrored vertex by vertex (a regular polygon becomes the polygon of the engine's own vertices,
     * mirrored), segment faces swap sides, event ranges are mirrored too.
     */
    public static void mirror(Recipe r) {
        r.gravityX = -r.gravityX;
        for (ShapeRecipe s : r.shapes) {
            mirror(s);
        }
        for (BodyRecipe b : r.bodies) {
            b.x = -b.x;
            b.angle = -b.angle;
            b.vx = -b.vx;
            b.omega = -b.omega;
        }
        for (JointRecipe j : r.joints) {
            j.x = -j.x;
            j.ax = -j.ax;
            j.bx = -j.bx;
        }
        for (SpringRecipe s : r.springs) {
            s.ax = -s.ax;
            s.bx = -s.bx;
        }
        for (MotorRecipe m : r.motors) {
            m.omega = -m.omega;
            m.vx = -m.vx;
        }
        for (ForceRecipe f : r.forces) {
            f.fx = -f.fx;
            f.px = -f.px;
            f.torque = -f.torque;
        }
        for (EmitterRecipe e : r.emitters) {
            e.x1 = -e.x1;
            e.x2 = -e.x2;
            e.angleDeg = 180f - e.angleDeg;
        }
        for (SegmentRecipe s : r.segments) {
            s.x1 = -s.x1;
            s.x2 = -s.x2;
            s.face = s.face == Landscape.FACE_LEFT ? Landscape.FACE_RIGHT
                    : s.face == Landscape.FACE_RIGHT ? Landscape.FACE_LEFT : s.face;
        }
        if (r.area != null) {
            float minX = r.area.minX;
            r.area.minX = -r.area.maxX;
            r.area.maxX = -minX;
        }
        for (EventRecipe e : r.events) {
            mirror(e);
        }
    }

    private static void mirror(EventRecipe e) {
        float p1 = e.p1;
        switch (e.type) {
            case Event.POSITION -> {
                e.p1 = -e.p3;
                e.p3 = -p1;
            }
            case Event.ANGLE -> {
                e.p1 = (float) (2 * Math.PI) - e.p2;
                e.p2 = (float) (2 * Math.PI) - p1;
            }
            case Event.ANGULAR_VELOCITY -> {
                e.p1 = -e.p2;
                e.p2 = -p1;
            }
            case Event.COLLISION -> {
                float right = e.p2;
                e.p2 = e.p4;
                e.p4 = right;
            }
            case Event.RELATIVE_COLLISION -> {
                e.p1 = (float) Math.PI - e.p2;
                e.p2 = (float) Math.PI - p1;
            }
            default -> {
            }
        }
    }

    private static void mirror(ShapeRecipe s) {
        s.centerX = -s.centerX;
        if (s.kind == ShapeRecipe.Kind.regularPolygon) {
            Polygon p = Shape.createRegularPolygon(s.radius, s.sides);
            s.vertices = new float[2 * p.getVertexCount()];
            for (int i = 0; i < p.getVertexCount(); i++) {
                s.vertices[2 * i] = p.getVertexX(i);
                s.vertices[2 * i + 1] = p.getVertexY(i);
            }
            s.kind = ShapeRecipe.Kind.polygon;
        }
        if (s.vertices != null) {
            // Negate x and reverse the order, so the winding stays the same.
            int n = s.vertices.length / 2;
            float[] m = new float[2 * n];
            for (int i = 0; i < n; i++) {
                m[2 * i] = -s.vertices[2 * (n - 1 - i)];
                m[2 * i + 1] = s.vertices[2 * (n - 1 - i) + 1];
            }
            s.vertices = m;
        }
        for (ShapeRecipe.Part p : s.parts) {
            mirror(p.shape);
            p.offsetX = -p.offsetX;
            p.angle = -p.angle;
        }
    }
}
