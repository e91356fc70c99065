package org.emini.io;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;

import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.world.World;
import org.emini.event.Event;
import org.emini.math.EMath;
import org.emini.particle.ParticleEmitter;
import org.emini.shape.MultiShape;
import org.emini.shape.Shape;

/**
 * Builds an engine {@link World} from a {@link PhyWorld} document through the engine's public API,
 * mapping the original's conventions (see <code>phy-mapping.md</code> in this package):
 *
 * <ul>
 * <li>Shapes: one engine shape per shape-list entry, shared by the bodies using it, as in the
 * original. A circle gets the original's whole-pixel radius; a polygon its vertices as stored
 * (either winding is fine); a line (2 vertices) a thin slab of {@link #setLineThickness(float)}
 * centred on it (approximated: the original's line has no thickness). Elasticity, friction and
 * mass are the stored FX values / 4096.</li>
 * <li>Bodies: position, velocity and the angle wrapped to [0, 2π] as stored; the angular velocity
 * negated (the original advances angle ← angle − ω·dt, the engine angle ← angle + ω·dt, with the
 * same rotation matrix); flags and collision layers as stored.</li>
 * <li>Joints, springs and motors on the bodies built, anchors body-local as stored; a rotational
 * motor's target negated, its cap (an impulse per tick in the original) divided by the timestep.</li>
 * <li>Events with their filters and targets in the engine's units (squared speeds as speeds,
 * angular velocity ranges negated, relative collision directions turned by π); set a listener on
 * the world to receive them.</li>
 * <li>Multishapes from the parts built (nested ones flattened), with the default material as in the
 * original; the landscape's segments as stored with their faces and its material.</li>
 * <li>Particle emitters with every stored setting (emit angles keep their sign), each with its own
 * seed; capacities above {@link #setParticleLimit(int)} are listed rather than allocated.</li>
 * <li>World record: gravity and the two damping fractions. Timestep and iterations keep the
 * engine's defaults (the file stores none).</li>
 * </ul>
 * Records whose engine feature is not available (scripts and their rows), records the engine
 * refuses and unusable records are listed in
 * {@link BuildResult#getUnsupported()}; records built differently from the original in
 * {@link BuildResult#getApproximations()}. Nothing is dropped silently.
 */
public final class WorldBuilder {
    /** The default thickness of the slab that stands in for a line shape (px). */
    public static final float DEFAULT_LINE_THICKNESS = 1f;
    /**
     * The default largest particle-emitter capacity built (2 MiB of particle state when full): a
     * file may ask for 2³¹ − 1 particles; the engine takes at most
     * {@link org.emini.particle.ParticleEmitter#MAX_PARTICLES}.
     */
    public static final int DEFAULT_PARTICLE_LIMIT = 1 << 16;

    private UserData userData;
    private float lineThickness = DEFAULT_LINE_THICKNESS;
    private int particleLimit = DEFAULT_PARTICLE_LIMIT;

    /** Creates a builder without a user-data factory. */
    public WorldBuilder() {
    }

    /**
     * Reads a world file and builds it, like the original's {@code World.loadWorld(reader,
     * userData)}.
     *
     * @param in the file's bytes (the stream is not closed)
     * @param userData the user-data factory, or null to discard the strings
     * @return the built world and what could not be built
     * @throws PhyFormatException if the data is not a world file the original accepts
     * @throws IOException if the stream fails
     */
    public static BuildResult loadWorld(InputStream in, UserData userData) throws IOException {
        return new WorldBuilder().setUserData(userData).build(new PhyReader().read(in));
    }

    /**
     * Sets the factory for user-data objects.
     *
     * @param userData the factory, or null to discard the strings
     * @return this builder
     */
    public WorldBuilder setUserData(UserData userData) {
        this.userData = userData;
        return this;
    }

    /**
     * Sets the thickness of the slab built for a line (two-vertex) shape.
     *
     * @param px the thickness (px), finite and &gt; 0
     * @return this builder
     */
    public WorldBuilder setLineThickness(float px) {
        if (!(EMath.isFinite(px) && px > 0f)) {
            throw new IllegalArgumentException("WorldBuilder.setLineThickness: px must be finite and > 0, was " + px);
        }
        lineThickness = px;
        return this;
    }

    /**
     * Sets the largest particle-emitter capacity built; emitters asking for more are listed as
     * unsupported instead of being built.
     *
     * @param particles the limit, &gt; 0
     * @return this builder
     */
    public WorldBuilder setParticleLimit(int particles) {
        if (particles <= 0) {
            throw new IllegalArgumentException("WorldBuilder.setParticleLimit: particles must be > 0, was " + particles);
        }
        particleLimit = particles;
        return this;
    }

    /**
     * Builds a new world from a document. The document is not changed. The user-data factory is
     * called for each stored string, by kind in this order: shapes, bodies, constraints, events
     * (each followed by its sensor body), particle emitters, the world record.
     *
     * @param document the document
     * @return the built world and what could not be built
     */
    public BuildResult build(PhyWorld document) {
        PhyWorld.checkNotNull("WorldBuilder.build", "document", document);
        World world = new World();
        BuildResult r = new BuildResult(document, world);
        boolean shapeData = PhyVersion.shapeAndBodyHaveUserData(document.getVersionWord());
        boolean otherData = PhyVersion.othersHaveUserData(document.getVersionWord());
        List<PhyShapeBase> shapes = document.getShapes();
        for (int i = 0; i < shapes.size(); i++) {
            PhyShapeBase s = shapes.get(i);
            // Multishapes exist only from version 9, which always stores their string.
            userData(r, s, s.isMultiShape() || shapeData, UserData.TYPE_SHAPE);
            Shape shape = s.isMultiShape() ? buildMultiShape((PhyMultiShape) s, i, r) : buildShape((PhyShape) s, i, r);
            r.setShape(i, shape);
            if (shape != null) {
                // The file's shape numbers are the World Designer's ids (the manual's GraphicsShapeSet).
                world.getShapeSet().put(i, shape);
                shape.setUserData(r.getUserData(s));
            }
        }
        List<PhyBody> bodies = document.getBodies();
        for (int i = 0; i < bodies.size(); i++) {
            userData(r, bodies.get(i), shapeData, UserData.TYPE_BODY);
            buildBody(bodies.get(i), i, r);
        }
        if (document.getLandscape() != null) {
            world.setLandscape(LandscapeMapping.build(document.getLandscape(), r));
        }
        List<PhyConstraint> constraints = document.getConstraints();
        for (int i = 0; i < constraints.size(); i++) {
            userData(r, constraints.get(i), otherData, UserData.TYPE_CONSTRAINT);
            Constraint c = ConstraintMapping.build(constraints.get(i), i, r, world.getTimestep());
            if (c != null) {
                ConstraintMapping.setUserData(c, r.getUserData(constraints.get(i)));
                world.addConstraint(c);
                r.setConstraint(i, c);
            }
        }
        ScriptMapping.build(document, world, r);
        for (int i = 0; i < document.getEvents().size(); i++) {
            buildEvent(document.getEvents().get(i), i, r, otherData, shapeData);
        }
        for (int i = 0; i < document.getParticleEmitters().size(); i++) {
            userData(r, document.getParticleEmitters().get(i), otherData, UserData.TYPE_PARTICLE);
            ParticleEmitter e = ParticleMapping.build(document.getParticleEmitters().get(i), i, r, particleLimit);
            if (e != null) {
                world.addParticleEmitter(e);
                r.setParticleEmitter(i, e);
            }
        }
        if (document.getSettings() != null) {
            userData(r, document.getSettings(), otherData, UserData.TYPE_WORLD);
            applySettings(document.getSettings(), world, r);
            world.setUserData(r.getUserData(document.getSettings()));
        }
        return r;
    }

    private void userData(BuildResult r, PhyElement e, boolean stored, int type) {
        if (stored && userData != null) {
            r.putUserData(e, userData.createNewUserData(e.getUserData(), type));
        }
    }

    /**
     * A multishape of the parts built so far; parts that are multishapes give their own parts (the
     * engine's parts are circles and polygons). Its material is the shape default, as in the original.
     */
    private static Shape buildMultiShape(PhyMultiShape m, int index, BuildResult r) {
        List<Shape> leaves = new ArrayList<Shape>();
        for (int p : m.getParts()) {
            Shape part = r.shapeAt(p);
            if (part == null) {
                r.unsupported(UnsupportedElement.Kind.MULTI_SHAPE, index,
                        BuildResult.missing("part", p, r.getDocument().getShapes().size()));
                return null;
            }
            if (part instanceof MultiShape) {
                MultiShape inner = (MultiShape) part;
                for (int k = 0; k < inner.getShapeCount(); k++) {
                    leaves.add(inner.getShape(k));
                }
            } else {
                leaves.add(part);
            }
        }
        if (leaves.isEmpty()) {
            r.unsupported(UnsupportedElement.Kind.MULTI_SHAPE, index, "a multishape without parts");
            return null;
        }
        return new MultiShape(leaves.toArray(new Shape[0]));
    }

    private Shape buildShape(PhyShape s, int index, BuildResult r) {
        int n = s.getVertexCount();
        Shape shape;
        try {
            if (n == 1) {
                int radius = s.getCircleRadius();
                if (radius <= 0) {
                    r.unsupported(UnsupportedElement.Kind.SHAPE, index, "a circle whose radius truncates to 0 px");
                    return null;
                }
                shape = Shape.createCircle(radius);
            } else if (n == 2) {
                float[] slab = lineSlab(s.getVertex(0), s.getVertex(1), lineThickness);
                if (slab == null) {
                    r.unsupported(UnsupportedElement.Kind.SHAPE, index, "a line of length 0");
                    return null;
                }
                shape = Shape.createPolygon(slab);
                r.approximated(UnsupportedElement.Kind.SHAPE, index, "a line, built as a slab " + lineThickness
                        + " px thick centred on it; on a dynamic body the original gives it infinite mass");
            } else if (n >= 3 && n <= Shape.MAX_VERTICES) {
                float[] xy = new float[2 * n];
                for (int i = 0; i < n; i++) {
                    xy[2 * i] = s.getVertex(i).getX();
                    xy[2 * i + 1] = s.getVertex(i).getY();
                }
                shape = Shape.createPolygon(xy);
            } else {
                r.unsupported(UnsupportedElement.Kind.SHAPE, index, n + " vertices: the original leaves such a shape "
                        + (n == 0 ? "empty" : "unusable (at most 12)"));
                return null;
            }
        } catch (IllegalArgumentException e) {
            r.unsupported(UnsupportedElement.Kind.SHAPE, index, e.getMessage());
            return null;
        }
        shape.setElasticity(unit(s.getElasticity(), UnsupportedElement.Kind.SHAPE, index, "elasticity", r));
        shape.setFriction(unit(s.getFriction(), UnsupportedElement.Kind.SHAPE, index, "friction", r));
        float mass = s.getMass();
        if (mass > 0f) {
            shape.setMass(mass);
        } else {
            r.approximated(UnsupportedElement.Kind.SHAPE, index, "mass " + mass + " is not > 0; mass 1 used");
        }
        return shape;
    }

    /** A factor the engine takes in [0, 1] (materials, damping): clamped, and noted when it was not. */
    static float unit(float value, UnsupportedElement.Kind kind, int index, String what, BuildResult r) {
        if (value >= 0f && value <= 1f) {
            return value;
        }
        float clamped = value < 0f ? 0f : 1f;
        r.approximated(kind, index, what + " " + value + " clamped to " + clamped);
        return clamped;
    }

    /**
     * The slab that stands in for a line (two-vertex) shape: the rectangle with the line as its
     * centre line, as x0, y0, … x3, y3 in the original's winding (counter-clockwise on a y-down
     * screen).
     *
     * @param a the line's first vertex (px)
     * @param b the line's second vertex (px)
     * @param thickness the slab's thickness (px), &gt; 0
     * @return the four corners, or null when the line has length 0
     */
    public static float[] lineSlab(PhyVector a, PhyVector b, float thickness) {
        float dx = b.getX() - a.getX();
        float dy = b.getY() - a.getY();
        float length = EMath.sqrt(dx * dx + dy * dy);
        if (!(length > 0f)) {
            return null;
        }
        float h = 0.5f * thickness / length;
        float nx = -dy * h;
        float ny = dx * h;
        return new float[] {a.getX() + nx, a.getY() + ny, b.getX() + nx, b.getY() + ny,
            b.getX() - nx, b.getY() - ny, a.getX() - nx, a.getY() - ny};
    }

    private static void buildBody(PhyBody b, int index, BuildResult r) {
        Shape shape = r.shapeAt(b.getShapeIndex());
        if (shape == null) {
            r.unsupported(UnsupportedElement.Kind.BODY, index,
                    BuildResult.missing("shape", b.getShapeIndex(), r.getDocument().getShapes().size()));
            return;
        }
        Body body = newBody(b, shape, UnsupportedElement.Kind.BODY, index, r);
        r.getWorld().addBody(body);
        r.setBody(index, body);
    }

    /** A body with the record's state (also an event's sensor body, which stays out of the world). */
    private static Body newBody(PhyBody b, Shape shape, UnsupportedElement.Kind kind, int index, BuildResult r) {
        Body body = new Body(b.getPosition().getX(), b.getPosition().getY(), shape, b.isDynamic());
        body.setRotatable(b.canRotate());
        body.setInteracting(b.isInteracting());
        body.setGravityAffected(b.isAffectedByGravity());
        body.setCollisionLayers(b.getCollisionLayers());
        body.setAngle(b.getAngle());
        // The original's angle decreases with a positive stored ω; the engine's grows with ω.
        float omega = -b.getAngularVelocity();
        if (b.isDynamic()) {
            body.setVelocity(b.getVelocity().getX(), b.getVelocity().getY());
            body.setAngularVelocity(omega);
        } else if (!b.getVelocity().equals(PhyVector.ZERO) || omega != 0f) {
            r.approximated(kind, index, "a static body with a stored velocity; the engine keeps static bodies at rest");
        }
        body.setUserData(r.getUserData(b));
        return body;
    }

    private void buildEvent(PhyEvent e, int index, BuildResult r, boolean otherData, boolean shapeData) {
        userData(r, e, otherData, UserData.TYPE_EVENT);
        Body sensor = null;
        if (e.getSensor() != null) {
            userData(r, e.getSensor(), shapeData, UserData.TYPE_BODY);
            Shape shape = r.shapeAt(e.getSensor().getShapeIndex());
            sensor = shape == null ? null : newBody(e.getSensor(), shape, UnsupportedElement.Kind.EVENT, index, r);
        }
        Event event = EventMapping.build(e, index, r, sensor, r.getWorld().getTimestep());
        if (event != null) {
            event.setUserData(r.getUserData(e));
            r.getWorld().addEvent(event);
            r.setEvent(index, event);
        }
    }

    private static void applySettings(PhyWorldSettings s, World world, BuildResult r) {
        world.setGravity(s.getGravity().getX(), s.getGravity().getY());
        world.setDampingLateral(unit(s.getDampingLinear(), UnsupportedElement.Kind.WORLD_SETTINGS, 0,
                "linear damping", r));
        world.setDampingRotational(unit(s.getDampingRotational(), UnsupportedElement.Kind.WORLD_SETTINGS, 0,
                "rotational damping", r));
    }
}
