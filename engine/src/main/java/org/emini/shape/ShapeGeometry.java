package org.emini.shape;

import org.emini.math.EMath;

/**
 * Area properties of a shape in its local frame, computed once at construction and handed to the
 * {@link Shape} constructor (which must run before the subclass can store anything).
 */
final class ShapeGeometry {
    final float area;
    final float centroidX;
    final float centroidY;
    /** Polar second moment of the area about the local origin, divided by the area. */
    final float unitInertia;
    final float boundingRadius;
    /** A polygon's cleaned counter-clockwise coordinates x0, y0, x1, ...; null for a circle. */
    final float[] vertices;
    /** The mass the shape starts with. */
    final float mass;

    private ShapeGeometry(float area, float centroidX, float centroidY, float unitInertia,
            float boundingRadius, float[] vertices, float mass) {
        this.area = area;
        this.centroidX = centroidX;
        this.centroidY = centroidY;
        this.unitInertia = unitInertia;
        this.boundingRadius = boundingRadius;
        this.vertices = vertices;
        this.mass = mass;
    }

    /** A disc; the caller has validated the arguments. */
    static ShapeGeometry ofCircle(float radius, float centerX, float centerY) {
        float offset2 = centerX * centerX + centerY * centerY;
        return new ShapeGeometry(EMath.PI * radius * radius, centerX, centerY,
                0.5f * radius * radius + offset2, EMath.sqrt(offset2) + radius, null,
                Shape.DEFAULT_MASS);
    }

    /**
     * A convex polygon given as x0, y0, x1, y1, ... in counter-clockwise order (positive signed
     * area), already validated.
     */
    static ShapeGeometry ofPolygon(float[] xy) {
        int n = xy.length / 2;
        // Sums are taken relative to the vertex average, close to the centroid, so that the
        // parallel-axis shifts below subtract small numbers and keep float precision.
        float rx = 0f;
        float ry = 0f;
        for (int i = 0; i < n; i++) {
            rx += xy[2 * i];
            ry += xy[2 * i + 1];
        }
        rx /= n;
        ry /= n;

        float twiceArea = 0f;
        float sx = 0f;
        float sy = 0f;
        float sj = 0f;
        float maxR2 = 0f;
        for (int i = 0; i < n; i++) {
            int k = i + 1 == n ? 0 : i + 1;
            float x1 = xy[2 * i] - rx;
            float y1 = xy[2 * i + 1] - ry;
            float x2 = xy[2 * k] - rx;
            float y2 = xy[2 * k + 1] - ry;
            float cross = x1 * y2 - x2 * y1;
            twiceArea += cross;
            sx += cross * (x1 + x2);
            sy += cross * (y1 + y2);
            sj += cross * (x1 * x1 + x1 * x2 + x2 * x2 + y1 * y1 + y1 * y2 + y2 * y2);
            float r2 = xy[2 * i] * xy[2 * i] + xy[2 * i + 1] * xy[2 * i + 1];
            if (r2 > maxR2) {
                maxR2 = r2;
            }
        }
        float area = 0.5f * twiceArea;
        float cx = sx / (3f * twiceArea);
        float cy = sy / (3f * twiceArea);
        // Polar moment about the reference point, then about the centroid, then about the origin.
        float jRef = sj / 12f;
        float jCentroid = jRef - area * (cx * cx + cy * cy);
        float centroidX = rx + cx;
        float centroidY = ry + cy;
        float jOrigin = jCentroid + area * (centroidX * centroidX + centroidY * centroidY);
        return new ShapeGeometry(area, centroidX, centroidY, jOrigin / area, EMath.sqrt(maxR2),
                xy, Shape.DEFAULT_MASS);
    }

    /**
     * A compound of parts placed in one frame: the masses add up, the centre of mass is the
     * mass-weighted mean of the parts' centroids and the inertia about the origin is the sum of
     * the parts' inertias about the origin (each already holds its parallel-axis term).
     */
    static ShapeGeometry ofParts(Shape[] parts) {
        float area = 0f;
        float mass = 0f;
        float mx = 0f;
        float my = 0f;
        float inertia = 0f;
        float radius = 0f;
        for (Shape p : parts) {
            area += p.getArea();
            mass += p.getMass();
            mx += p.getMass() * p.getCentroidX();
            my += p.getMass() * p.getCentroidY();
            inertia += p.getInertia();
            radius = Math.max(radius, p.getBoundingRadius());
        }
        return new ShapeGeometry(area, mx / mass, my / mass, inertia / mass, radius, null, mass);
    }
}
