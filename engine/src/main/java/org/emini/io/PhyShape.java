package org.emini.io;

import java.util.Arrays;

/**
 * A shape record: vertices in the shape's local frame (the body's reference point is the origin),
 * elasticity, friction and mass. The vertex count decides the kind: 1 is a circle centred on the
 * origin whose radius is the vertex's distance from it ({@link #getCircleRadius()}), 2 a line
 * segment (zero area), 3 to 12 a convex polygon listed counter-clockwise as seen on a y-down
 * screen, 0 an empty shape (the landscape's material record). The original leaves a shape with
 * more than 12 vertices unusable.
 */
public final class PhyShape extends PhyShapeBase {
    private static final PhyVector[] NO_VERTICES = new PhyVector[0];

    private int legacyId;
    private PhyVector[] vertices = NO_VERTICES;
    private int elasticity;
    private int friction = PhyFixed.FX_ONE / 4;
    private int mass = PhyFixed.FX_ONE;

    /** Creates an empty shape with the original's defaults: elasticity 0, friction 0.25, mass 1. */
    public PhyShape() {
    }

    /**
     * Creates a shape with vertices and the default material.
     *
     * @param vertices the vertices (px, raw FX), at most 255
     */
    public PhyShape(PhyVector... vertices) {
        setVertices(vertices);
    }

    @Override
    public boolean isMultiShape() {
        return false;
    }

    /**
     * The legacy id byte that records of version words up to 0x0200 start with; ignored by the
     * original and written only in those versions.
     *
     * @return 0 to 255
     */
    public int getLegacyId() {
        return legacyId;
    }

    /**
     * Sets the legacy id byte.
     *
     * @param legacyId 0 to 255
     */
    public void setLegacyId(int legacyId) {
        this.legacyId = PhyWorld.checkU8("PhyShape.setLegacyId", "legacyId", legacyId);
    }

    /**
     * The number of vertices.
     *
     * @return 0 to 255
     */
    public int getVertexCount() {
        return vertices.length;
    }

    /**
     * A vertex.
     *
     * @param i 0 to {@link #getVertexCount()} − 1
     * @return the vertex (px, raw FX)
     */
    public PhyVector getVertex(int i) {
        return vertices[i];
    }

    /**
     * All vertices.
     *
     * @return a copy of the vertex array
     */
    public PhyVector[] getVertices() {
        return vertices.clone();
    }

    /**
     * Replaces the vertices.
     *
     * @param vertices the vertices (copied), at most 255, none null
     * @throws IllegalArgumentException if there are more than 255 or one is null
     */
    public void setVertices(PhyVector... vertices) {
        if (vertices == null || vertices.length > 255) {
            throw new IllegalArgumentException("PhyShape.setVertices: 0 to 255 vertices, got "
                    + (vertices == null ? "null" : Integer.toString(vertices.length)));
        }
        for (PhyVector v : vertices) {
            PhyWorld.checkNotNull("PhyShape.setVertices", "vertex", v);
        }
        this.vertices = vertices.clone();
    }

    /**
     * Whether the shape is a circle (one vertex).
     *
     * @return true for one vertex
     */
    public boolean isCircle() {
        return vertices.length == 1;
    }

    /**
     * The radius of a circle as the fixed-point original computes it: the vertex's distance from
     * the origin truncated to whole pixels (see {@link PhyFixed#circleRadius(int, int)}).
     *
     * @return the radius in px, or 0 when the shape is not a circle
     */
    public int getCircleRadius() {
        return isCircle() ? PhyFixed.circleRadius(vertices[0].getXRaw(), vertices[0].getYRaw()) : 0;
    }

    /**
     * The elasticity as stored (FX, 4096 = 1.0).
     *
     * @return the raw value
     */
    public int getElasticityRaw() {
        return elasticity;
    }

    /**
     * Sets the elasticity as stored.
     *
     * @param raw the raw FX value
     */
    public void setElasticityRaw(int raw) {
        elasticity = raw;
    }

    /**
     * The elasticity (restitution factor; a contact uses the product of both shapes').
     *
     * @return raw / 4096, 0 to 1 in designer files
     */
    public float getElasticity() {
        return PhyFixed.fx(elasticity);
    }

    /**
     * The friction factor as stored (FX, 4096 = 1.0).
     *
     * @return the raw value
     */
    public int getFrictionRaw() {
        return friction;
    }

    /**
     * Sets the friction factor as stored.
     *
     * @param raw the raw FX value
     */
    public void setFrictionRaw(int raw) {
        friction = raw;
    }

    /**
     * The friction factor (a contact uses the product of both shapes').
     *
     * @return raw / 4096, 0 to 1 in designer files
     */
    public float getFriction() {
        return PhyFixed.fx(friction);
    }

    /**
     * The mass as stored (FX); files of version words below 0x0500 store none and read as 1.0.
     *
     * @return the raw value
     */
    public int getMassRaw() {
        return mass;
    }

    /**
     * Sets the mass as stored.
     *
     * @param raw the raw FX value
     */
    public void setMassRaw(int raw) {
        mass = raw;
    }

    /**
     * The mass (a ratio).
     *
     * @return raw / 4096
     */
    public float getMass() {
        return PhyFixed.fx(mass);
    }

    static PhyShape read(PhyInput in) throws PhyFormatException {
        int v = in.version();
        PhyShape s = new PhyShape();
        if (PhyVersion.shapeHasLegacyId(v)) {
            s.legacyId = in.u8("legacy id");
        }
        int n = in.u8("vertex count");
        PhyVector[] vs = new PhyVector[n];
        for (int i = 0; i < n; i++) {
            vs[i] = in.vector("vertex", i);
        }
        s.vertices = vs;
        s.elasticity = in.i32("elasticity");
        s.friction = in.i32("friction");
        if (PhyVersion.shapeHasMass(v)) {
            s.mass = in.i32("mass");
        }
        s.readUserData(in, PhyVersion.shapeAndBodyHaveUserData(v));
        return s;
    }

    void write(PhyOutput out) {
        int v = out.version();
        if (PhyVersion.shapeHasLegacyId(v)) {
            out.u8(legacyId);
        }
        out.u8(vertices.length);
        for (PhyVector p : vertices) {
            out.vector(p);
        }
        out.i32(elasticity);
        out.i32(friction);
        if (PhyVersion.shapeHasMass(v)) {
            out.i32(mass);
        } else if (mass != PhyFixed.FX_ONE) {
            throw new IllegalArgumentException("PhyWriter.write: version " + PhyVersion.toString(v)
                    + " stores no shape mass; " + out.describe() + " has mass " + getMass() + " instead of 1");
        }
        out.userData(PhyVersion.shapeAndBodyHaveUserData(v), this);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PhyShape)) {
            return false;
        }
        PhyShape s = (PhyShape) o;
        return legacyId == s.legacyId && Arrays.equals(vertices, s.vertices) && elasticity == s.elasticity
                && friction == s.friction && mass == s.mass && userDataEquals(s);
    }

    @Override
    public int hashCode() {
        return ((Arrays.hashCode(vertices) * 31 + elasticity) * 31 + friction) * 31 + mass + userDataHash();
    }

    @Override
    public String toString() {
        return "PhyShape[" + vertices.length + " vertices, elasticity " + getElasticity() + ", friction "
                + getFriction() + ", mass " + getMass() + "]";
    }
}
