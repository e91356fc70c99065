package org.emini.shape;

import org.emini.math.EMath;

/**
 * A collision shape with its material and mass: a {@link Circle}, a convex {@link Polygon}, or a
 * {@link MultiShape} made of several of them.
 *
 * <p>Coordinates are local: the origin is the position and the centre of rotation of the body
 * that uses the shape. Shapes are not re-centred automatically; an off-centre shape rotates about
 * its origin, and its inertia is taken about that origin (see {@link #getInertia()}).
 *
 * <p>Geometry never changes after construction, so one shape may be shared by many bodies.
 * Material and mass can be changed; they affect every body sharing the shape.
 *
 * <p>Sizes: a shape must be at least {@link #MIN_SIZE} (0.25 px) across everywhere (a circle's
 * diameter, a polygon's narrowest width); smaller ones are refused with
 * {@link InvalidShapeException.Rule#TOO_SMALL}. Resting bodies overlap their supports by the
 * solver's linear slop (0.05 px by default, {@code SolverSettings}), which is a fifth of the
 * smallest shape; measured at the default settings, a 0.2 px box stands in a stack of three and a
 * 0.1 px one does not, and a 0.001 px box ends 50 times its size inside the ground. Boxes up to
 * 1,000 px rest and stack as well as 20 px ones; a polygon's sides may differ by up to the factor
 * 1 / {@link Polygon#RELATIVE_TOLERANCE}.
 *
 * <p>A contact's friction and elasticity are the products of the two shapes' factors (as in the
 * original engine): a bouncy ball needs a bouncy ground too.
 *
 * <pre>{@code
 * Circle ball = Shape.createCircle(10);
 * ball.setElasticity(0.8f);                  // 0..1; setElasticityPercent(80) as in the original
 * ball.setMass(2);                           // every body using this shape weighs 2
 * Polygon ground = Shape.createRectangle(400, 20);
 * ground.setElasticity(1f);                  // 0.8 × 1: the ball bounces back to 64% of its height
 * Polygon wedge = Shape.createPolygon(0, 0, 40, 0, 0, -30);   // convex, either winding
 * }</pre>
 */
public abstract class Shape {
    /** Type code of {@link Circle}. */
    public static final int TYPE_CIRCLE = 0;
    /** Type code of {@link Polygon}. */
    public static final int TYPE_POLYGON = 1;
    /** Type code of {@link MultiShape}. */
    public static final int TYPE_MULTI = 2;
    /** The largest number of vertices a polygon may have, as in the original engine. */
    public static final int MAX_VERTICES = 12;
    /** Mass of a new shape. */
    public static final float DEFAULT_MASS = 1f;
    /** Friction factor of a new shape. */
    public static final float DEFAULT_FRICTION = 0.25f;
    /** Elasticity of a new shape. */
    public static final float DEFAULT_ELASTICITY = 0f;
    /** The smallest width a shape may have anywhere (px): five times the default linear slop. */
    public static final float MIN_SIZE = 0.25f;
    /**
     * The farthest a shape may reach from its local origin (px): 10⁷, the largest coordinate at which
     * float still resolves a pixel to about one part in a thousand, the range the particles and the
     * harness accept too. Beyond it boxes, grids and sweeps overflow.
     */
    public static final float MAX_EXTENT = 1e7f;

    private final float area;
    private final float centroidX;
    private final float centroidY;
    private final float unitInertia;
    private final float boundingRadius;
    // A field, not an override per class: the engine's hot loops ask every shape its type, and a call
    // site that meets all three classes would be a virtual call there.
    private final int type;

    private float mass;
    private float inverseMass;
    private float inertia;
    private float inverseInertia;
    private float friction = DEFAULT_FRICTION;
    private float elasticity = DEFAULT_ELASTICITY;
    private int id = -1;
    private Object userData;

    Shape(ShapeGeometry geometry, int type) {
        this.type = type;
        area = geometry.area;
        centroidX = geometry.centroidX;
        centroidY = geometry.centroidY;
        unitInertia = geometry.unitInertia;
        boundingRadius = geometry.boundingRadius;
        if (!(boundingRadius <= MAX_EXTENT)) {
            throw new InvalidShapeException(InvalidShapeException.Rule.TOO_LARGE, -1, getClass().getSimpleName()
                    + ": rule TOO_LARGE: it reaches " + boundingRadius + " px from its origin, beyond Shape.MAX_EXTENT ("
                    + MAX_EXTENT + " px)");
        }
        applyMass(geometry.mass);
    }

    /**
     * Creates a circle centred on the origin.
     *
     * @param radius the radius (px), finite and at least {@link #MIN_SIZE} / 2
     * @return the circle
     * @throws InvalidShapeException if the radius is not finite, not positive or too small
     */
    public static Circle createCircle(float radius) {
        return new Circle(radius);
    }

    /**
     * Creates a rectangle centred on the origin with its sides along the axes.
     *
     * @param width the extent along x (px), finite and at least {@link #MIN_SIZE}
     * @param height the extent along y (px), finite and at least {@link #MIN_SIZE}
     * @return the rectangle
     * @throws IllegalArgumentException if a size is not finite or not positive
     *     ({@link InvalidShapeException} if it is below {@link #MIN_SIZE})
     */
    public static Polygon createRectangle(float width, float height) {
        checkSize("Shape.createRectangle", "width", width);
        checkSize("Shape.createRectangle", "height", height);
        checkMinSize("Shape.createRectangle", "width", width);
        checkMinSize("Shape.createRectangle", "height", height);
        float hw = 0.5f * width;
        float hh = 0.5f * height;
        return new Polygon(-hw, -hh, hw, -hh, hw, hh, -hw, hh);
    }

    /**
     * Creates a regular polygon centred on the origin; vertex 0 is at angle 0, that is at
     * (radius, 0), and vertex i at angle 2πi/vertexCount.
     *
     * @param radius the circumradius (px), finite and &gt; 0; the polygon must be at least
     *     {@link #MIN_SIZE} across (a triangle is 1.5 radii across, a square 1.41)
     * @param vertexCount the number of vertices, 3 to {@link #MAX_VERTICES}
     * @return the polygon
     * @throws IllegalArgumentException if the radius is not finite or not positive, or the vertex
     *     count is out of range or the polygon too small ({@link InvalidShapeException} for these)
     */
    public static Polygon createRegularPolygon(float radius, int vertexCount) {
        checkSize("Shape.createRegularPolygon", "radius", radius);
        if (vertexCount < 3) {
            throw new InvalidShapeException(InvalidShapeException.Rule.TOO_FEW_VERTICES, -1,
                    "Shape.createRegularPolygon: rule TOO_FEW_VERTICES: vertexCount " + vertexCount
                            + " is below 3");
        }
        if (vertexCount > MAX_VERTICES) {
            throw new InvalidShapeException(InvalidShapeException.Rule.TOO_MANY_VERTICES, -1,
                    "Shape.createRegularPolygon: rule TOO_MANY_VERTICES: vertexCount " + vertexCount
                            + " is above " + MAX_VERTICES);
        }
        float[] xy = new float[2 * vertexCount];
        for (int i = 0; i < vertexCount; i++) {
            float angle = EMath.TWO_PI * i / vertexCount;
            xy[2 * i] = radius * EMath.cos(angle);
            xy[2 * i + 1] = radius * EMath.sin(angle);
        }
        return new Polygon(xy);
    }

    /**
     * Creates a convex polygon from local coordinates; see {@link Polygon#Polygon(float...)} for
     * the validation and cleaning applied.
     *
     * @param xy the coordinates x0, y0, x1, y1, ... (px), in either winding
     * @return the polygon
     * @throws InvalidShapeException if the coordinates do not describe a convex polygon
     */
    public static Polygon createPolygon(float... xy) {
        return new Polygon(xy);
    }

    /**
     * Creates a multi-shape from convex parts placed in one local frame; see
     * {@link MultiShape#MultiShape(Shape...)}.
     *
     * @param parts circles and polygons, at least one
     * @return the multi-shape
     * @throws IllegalArgumentException if there are no parts, or a part is null or a multi-shape
     */
    public static MultiShape createMultiShape(Shape... parts) {
        return new MultiShape(parts);
    }

    private static void checkMinSize(String place, String name, float value) {
        if (value < MIN_SIZE) {
            throw new InvalidShapeException(InvalidShapeException.Rule.TOO_SMALL, -1, place + ": rule TOO_SMALL: "
                    + name + " " + value + " px is below Shape.MIN_SIZE (" + MIN_SIZE + " px)");
        }
    }

    private static void checkSize(String place, String name, float value) {
        if (!(EMath.isFinite(value) && value > 0f)) {
            throw new IllegalArgumentException(
                    place + ": " + name + " must be finite and > 0, got " + value);
        }
    }

    /**
     * The kind of shape.
     *
     * @return {@link #TYPE_CIRCLE}, {@link #TYPE_POLYGON} or {@link #TYPE_MULTI}
     */
    public final int getType() {
        return type;
    }

    /**
     * Computes the axis-aligned bounding box of the shape placed at a position and rotation.
     * A rotation maps a local point (lx, ly) to (c·lx − s·ly, s·lx + c·ly).
     *
     * @param x the x of the local origin in the world (px)
     * @param y the y of the local origin in the world (px)
     * @param c the cosine of the rotation angle
     * @param s the sine of the rotation angle
     * @param out receives minX, minY, maxX, maxY at indices 0 to 3
     */
    public abstract void computeAabb(float x, float y, float c, float s, float[] out);

    /**
     * The mass.
     *
     * @return the mass, finite and &gt; 0
     */
    public float getMass() {
        return mass;
    }

    /**
     * Sets the mass; the inertia follows (uniform density over the area).
     *
     * @param mass the mass, finite and &gt; 0 (a ratio: only mass ratios matter)
     * @throws IllegalArgumentException if the mass is not finite or not positive, or so small or
     *     large that the mass, inertia or their inverses overflow a float
     */
    public void setMass(float mass) {
        if (!(EMath.isFinite(mass) && mass > 0f)) {
            throw new IllegalArgumentException(
                    "Shape.setMass: mass must be finite and > 0, got " + mass);
        }
        float inertia = mass * unitInertia;
        if (!(EMath.isFinite(1f / mass) && inertia > 0f && EMath.isFinite(inertia) && EMath.isFinite(1f / inertia))) {
            throw new IllegalArgumentException("Shape.setMass: mass " + mass + " gives this shape an inertia of "
                    + inertia + ", whose inverse a float cannot hold; choose a mass nearer 1 (only ratios matter)");
        }
        applyMass(mass);
    }

    // Not overridable: the constructor calls it before any subclass state exists.
    private void applyMass(float mass) {
        this.mass = mass;
        inverseMass = 1f / mass;
        inertia = mass * unitInertia;
        inverseInertia = 1f / inertia;
    }

    /**
     * The inverse of the mass, cached.
     *
     * @return 1 / mass
     */
    public float getInverseMass() {
        return inverseMass;
    }

    /**
     * The moment of inertia about the local origin (the body's centre of rotation): the polar
     * second moment of the area about the origin, scaled to the mass. For an off-centre shape this
     * includes the parallel-axis term mass·|centroid|² once.
     *
     * @return the inertia (mass·px²), &gt; 0
     */
    public float getInertia() {
        return inertia;
    }

    /**
     * The inverse of the inertia, cached and recomputed when the mass changes.
     *
     * @return 1 / inertia
     */
    public float getInverseInertia() {
        return inverseInertia;
    }

    /**
     * The friction factor; a contact uses the product of both shapes' factors.
     *
     * @return the friction factor in [0, 1]
     */
    public float getFriction() {
        return friction;
    }

    /**
     * Sets the friction factor.
     *
     * @param friction the factor in [0, 1]
     * @throws IllegalArgumentException if the factor is NaN or outside [0, 1]
     */
    public void setFriction(float friction) {
        if (!(friction >= 0f && friction <= 1f)) {
            throw new IllegalArgumentException(
                    "Shape.setFriction: friction must be in [0, 1], got " + friction);
        }
        this.friction = friction;
    }

    /**
     * Sets the friction factor in percent, like the original engine's integer setter.
     *
     * @param percent the factor in percent, 0 to 100
     * @throws IllegalArgumentException if the value is outside [0, 100]
     */
    public void setFrictionPercent(int percent) {
        if (percent < 0 || percent > 100) {
            throw new IllegalArgumentException(
                    "Shape.setFrictionPercent: percent must be in [0, 100], got " + percent);
        }
        friction = percent / 100f;
    }

    /**
     * The elasticity; a contact uses the product of both shapes' elasticities.
     *
     * @return the elasticity in [0, 1]
     */
    public float getElasticity() {
        return elasticity;
    }

    /**
     * Sets the elasticity.
     *
     * @param elasticity the elasticity in [0, 1]
     * @throws IllegalArgumentException if the value is NaN or outside [0, 1]
     */
    public void setElasticity(float elasticity) {
        if (!(elasticity >= 0f && elasticity <= 1f)) {
            throw new IllegalArgumentException(
                    "Shape.setElasticity: elasticity must be in [0, 1], got " + elasticity);
        }
        this.elasticity = elasticity;
    }

    /**
     * Sets the elasticity in percent, like the original engine's integer setter.
     *
     * @param percent the elasticity in percent, 0 to 100
     * @throws IllegalArgumentException if the value is outside [0, 100]
     */
    public void setElasticityPercent(int percent) {
        if (percent < 0 || percent > 100) {
            throw new IllegalArgumentException(
                    "Shape.setElasticityPercent: percent must be in [0, 100], got " + percent);
        }
        elasticity = percent / 100f;
    }

    /**
     * The area.
     *
     * @return the area (px²), &gt; 0
     */
    public float getArea() {
        return area;
    }

    /**
     * The x of the centroid (centre of mass) in local coordinates.
     *
     * @return the centroid's x (px)
     */
    public float getCentroidX() {
        return centroidX;
    }

    /**
     * The y of the centroid (centre of mass) in local coordinates.
     *
     * @return the centroid's y (px)
     */
    public float getCentroidY() {
        return centroidY;
    }

    /**
     * The largest distance of any point of the shape from the local origin.
     *
     * @return the bounding radius (px)
     */
    public float getBoundingRadius() {
        return boundingRadius;
    }

    /**
     * A copy moved by (dx, dy) in the local frame, with the same mass and material.
     */
    abstract Shape translated(float dx, float dy);

    /**
     * A new shape with the same geometry, mass, material, id and user data (the original's
     * {@code Shape(Shape)}). Bodies and events tell shapes apart by the object, so the copy is a
     * different shape to them.
     *
     * @return the copy
     */
    public Shape copy() {
        Shape copy = translated(0f, 0f);
        copy.id = id;
        copy.userData = userData;
        return copy;
    }

    /**
     * The shape's id: its index in a {@link ShapeSet} (a world file's shapes get their index in the
     * file, the World Designer's numbering), or what {@link #setId} set; −1 until then.
     *
     * @return the id, or −1
     */
    public int getId() {
        return id;
    }

    /**
     * Sets the shape's id, for an application that looks up images or sounds by shape.
     *
     * @param id the id, &ge; −1 (−1: none)
     */
    public void setId(int id) {
        if (id < -1) {
            throw new IllegalArgumentException("Shape.setId: id must be >= -1, was " + id);
        }
        this.id = id;
    }

    /**
     * The application's object attached to this shape.
     *
     * @return the user data, or null
     */
    public Object getUserData() {
        return userData;
    }

    /**
     * Attaches an application object to this shape (shared by every body using it).
     *
     * @param userData any object, or null
     */
    public void setUserData(Object userData) {
        this.userData = userData;
    }

    /** Copies mass, friction and elasticity from another shape. */
    void copyMaterial(Shape other) {
        applyMass(other.mass);
        friction = other.friction;
        elasticity = other.elasticity;
    }
}
