package org.emini.shape;

/**
 * A shape made of several convex parts (circles and polygons) placed in one local frame; the whole
 * may be concave: an L, a U, a hook. Bodies use it like any shape.
 *
 * <p>Parts are given in the multi-shape's local frame, which is the body's frame: a polygon's
 * vertices are already local coordinates, and a circle's offset centre ({@link Circle#Circle(float,
 * float, float)}) places it. As for every shape, the body rotates about the local origin and
 * gravity acts there, so build the parts around their common centre of mass, or call
 * {@link #centred()}, for the body to move as the solid it depicts.
 *
 * <p>Mass and inertia come from the parts as they are when the multi-shape is made (later changes
 * to a part do not reach it): the mass is the sum of the parts' masses, the centre of mass the
 * mass-weighted mean of their centroids, and the inertia about the origin the sum of the parts'
 * inertias about the origin, each being the part's own inertia about its centroid plus its mass
 * times its squared distance from the origin (the parallel-axis theorem). {@link #setMass(float)}
 * rescales all of them together. The material is the multi-shape's own, as in the original engine:
 * contacts of any part use the multi-shape's friction and elasticity, not the part's.
 *
 * <p>Parts may overlap; the area and mass then count the overlap twice. Collision runs part by
 * part, so a body pair has one contact per pair of parts that touch.
 */
public final class MultiShape extends Shape {
    private final Shape[] parts;

    /**
     * Creates a multi-shape from convex parts placed in one local frame.
     *
     * @param parts circles and polygons, at least one; the array is copied, the parts are shared
     * @throws IllegalArgumentException if there are no parts, or a part is null or a multi-shape
     */
    public MultiShape(Shape... parts) {
        super(ShapeGeometry.ofParts(validated(parts)), TYPE_MULTI);
        this.parts = parts.clone();
    }

    private static Shape[] validated(Shape[] parts) {
        if (parts == null || parts.length == 0) {
            throw new IllegalArgumentException("MultiShape: at least one part is needed, got "
                    + (parts == null ? "null" : "none"));
        }
        for (int i = 0; i < parts.length; i++) {
            if (parts[i] == null) {
                throw new IllegalArgumentException("MultiShape: part " + i + " is null");
            }
            if (parts[i].getType() == TYPE_MULTI) {
                throw new IllegalArgumentException("MultiShape: part " + i
                        + " is a multi-shape; give its parts instead");
            }
        }
        return parts;
    }

    /**
     * The number of parts.
     *
     * @return the part count, at least 1
     */
    public int getShapeCount() {
        return parts.length;
    }

    /**
     * A part.
     *
     * @param i the part index, 0 to {@link #getShapeCount()} − 1
     * @return the part, a {@link Circle} or a {@link Polygon}
     * @throws IndexOutOfBoundsException if the index is out of range
     */
    public Shape getShape(int i) {
        if (i < 0 || i >= parts.length) {
            throw new IndexOutOfBoundsException("MultiShape.getShape: index " + i + " of "
                    + parts.length);
        }
        return parts[i];
    }

    /**
     * A copy whose parts are translated so that the centre of mass is at the local origin, with the
     * same mass and material. Its inertia is smaller by mass·|centre of mass|².
     *
     * @return the centred multi-shape
     */
    public MultiShape centred() {
        return translated(-getCentroidX(), -getCentroidY());
    }

    @Override
    MultiShape translated(float dx, float dy) {
        Shape[] moved = new Shape[parts.length];
        for (int i = 0; i < parts.length; i++) {
            moved[i] = parts[i].translated(dx, dy);
        }
        MultiShape m = new MultiShape(moved);
        m.copyMaterial(this);
        return m;
    }

    @Override
    public void computeAabb(float x, float y, float c, float s, float[] out) {
        parts[0].computeAabb(x, y, c, s, out);
        float minX = out[0];
        float minY = out[1];
        float maxX = out[2];
        float maxY = out[3];
        for (int i = 1; i < parts.length; i++) {
            parts[i].computeAabb(x, y, c, s, out);
            minX = Math.min(minX, out[0]);
            minY = Math.min(minY, out[1]);
            maxX = Math.max(maxX, out[2]);
            maxY = Math.max(maxY, out[3]);
        }
        out[0] = minX;
        out[1] = minY;
        out[2] = maxX;
        out[3] = maxY;
    }

    @Override
    public String toString() {
        return "MultiShape[" + parts.length + " parts, mass " + getMass() + "]";
    }
}
