package org.emini.dynamics;

import org.emini.internal.Check;
import org.emini.math.EMath;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;

/**
 * A rigid body: a shape placed in the world with a position, an angle and velocities.
 *
 * <p>The body's position is the shape's local origin, which is also its centre of mass and centre
 * of rotation (as in the original engine). Angles are in radians; a rotation by θ maps a local point
 * (x, y) to (x·cosθ − y·sinθ, x·sinθ + y·cosθ), so on a y-down screen a growing angle (a positive
 * angular velocity) turns the body clockwise.
 *
 * <p>A body is of one of three kinds. Static bodies never move and have infinite mass whatever
 * their shape's mass. Dynamic bodies move under gravity, contacts, constraints and the forces applied
 * to them. Kinematic bodies ({@link #setKinematic(boolean)}) move by the velocity the application
 * sets, every tick, and nothing else: infinite mass, no gravity, no damping, forces and impulses
 * ignored; they push dynamic bodies and carry them by friction, and pass through static and other
 * kinematic bodies and the landscape (a moving platform, an elevator, a paddle). All setters refuse
 * NaN and infinite values with an {@link IllegalArgumentException} naming the call.
 *
 * <p>Which pairs collide: see {@link #setCollisionLayers(int)} (the original engine's layers) and
 * {@link #setCategoryBits(int)} (Box2D's categories, mask and group); both must allow a pair.
 *
 * <pre>{@code
 * Shape crate = Shape.createRectangle(20, 20);   // mass, friction and elasticity live on the shape
 * Body body = new Body(100, 50, crate, true);    // dynamic, at (100, 50)
 * body.setAngleDegrees(30);
 * body.setVelocity(40, -80);                     // px/s, y down the screen
 * world.addBody(body);
 * world.tick();
 * body.applyImpulse(0, -50);                     // a kick upwards: Δv = j / m at once
 * }</pre>
 */
public final class Body {
    private Shape shape;
    private boolean dynamic;
    private boolean kinematic;
    private boolean rotatable = true;
    private boolean interacting = true;
    private boolean gravityAffected = true;
    private boolean bullet;
    private int layers;
    private int categoryBits = DEFAULT_CATEGORY_BITS;
    private int maskBits = DEFAULT_MASK_BITS;
    private int groupIndex;
    private Object userData;

    // State: position of the shape origin (px), accumulated angle (rad) and its rotation (c, s).
    float x;
    float y;
    float angle;
    float c = 1f;
    float s;
    float vx;
    float vy;
    float w;

    // Accumulated force (mass·px/s²) and torque for the tick numbered forceTick; a body the tick
    // does not simulate (static, or frozen outside the simulation area) keeps them, so they count
    // only while forceTick is the world's current tick.
    float forceX;
    float forceY;
    float torque;
    long forceTick;

    // Bookkeeping owned by the world.
    Simulation world;
    int id = -1;
    int worldIndex = -1;
    // The keys of the shape's parts in the world's PartKeys, one per part: each names its broadphase proxy.
    int[] partKeys = NO_KEYS;
    boolean proxyDirty;
    int solverIndex;
    // Where the last tick's StepData lists this body (checked there).
    int stepIndex = -1;
    // Sleeping (see Sleep): the rest time, and the ring of the island it sleeps with.
    boolean sleeping;
    boolean sleepAllowed = true;
    float sleepTime;
    Body sleepNext;
    // A sensor: collides with nothing, reports what overlaps it (SensorSet), sorted by id.
    boolean sensor;
    Body[] visitors = NO_BODIES;
    int visitorCount;
    private static final Body[] NO_BODIES = new Body[0];
    private static final int[] NO_KEYS = new int[0];
    // Bodies this one never collides with (World.disableCollision): a joint's "collide connected" off.
    Body[] noCollide;
    int noCollideCount;
    Contact contactList;
    int contactCount;
    // Simulated in the current tick: dynamic and inside the simulation area.
    boolean awake;
    // The world's landscape epoch when this body last looked for its segments; −1 to look again.
    int landscapeEpoch = -1;

    /** The category bits of a new body: category 0 alone (Box2D's default, {@code 0x0001}). */
    public static final int DEFAULT_CATEGORY_BITS = 1;
    /** The mask bits of a new body: every category ({@code 0xFFFFFFFF}). */
    public static final int DEFAULT_MASK_BITS = -1;

    /**
     * Creates a body.
     *
     * @param x the x position of the shape's origin (px)
     * @param y the y position of the shape's origin (px)
     * @param shape the shape, which may be shared by many bodies
     * @param dynamic true for a body that moves, false for a static body
     */
    public Body(float x, float y, Shape shape, boolean dynamic) {
        this.shape = Check.notNull("Body(x, y, shape, dynamic)", "shape", shape);
        this.x = Check.finite("Body(x, y, shape, dynamic)", "x", x);
        this.y = Check.finite("Body(x, y, shape, dynamic)", "y", y);
        this.dynamic = dynamic;
    }

    /**
     * Creates a copy of a body (same shape, which is shared, same state and flags, same user data),
     * not yet in any world.
     *
     * @param other the body to copy
     */
    public Body(Body other) {
        shape = other.shape;
        dynamic = other.dynamic;
        kinematic = other.kinematic;
        rotatable = other.rotatable;
        interacting = other.interacting;
        gravityAffected = other.gravityAffected;
        bullet = other.bullet;
        layers = other.layers;
        categoryBits = other.categoryBits;
        maskBits = other.maskBits;
        groupIndex = other.groupIndex;
        userData = other.userData;
        x = other.x;
        y = other.y;
        angle = other.angle;
        c = other.c;
        s = other.s;
        vx = other.vx;
        vy = other.vy;
        w = other.w;
    }

    /**
     * A copy of this body (the original's {@code copy()}): {@link #Body(Body)}.
     *
     * @return the copy, not in any world
     */
    public Body copy() {
        return new Body(this);
    }

    /**
     * The outline of the body's shape in world coordinates, where the body is now (the original's
     * {@code getVertices()}), for drawing. A polygon gives its corners in order; a circle one point,
     * on its rim at the body's angle (as in the original, where a circle is a shape with one
     * vertex: its distance from the centre is the radius). A multi-shape gives its parts'
     * outlines one after another (a circle part as its rim point); use
     * {@link org.emini.shape.MultiShape#getShape(int)} to tell them apart. Allocates the array.
     *
     * @return x0, y0, x1, y1, ... (px)
     */
    public float[] getVertices() {
        int n = outlineLength(shape);
        float[] out = new float[n];
        writeOutline(shape, out, 0);
        return out;
    }

    private static int outlineLength(Shape s) {
        if (s instanceof Polygon) {
            return 2 * ((Polygon) s).getVertexCount();
        }
        if (s instanceof MultiShape) {
            MultiShape m = (MultiShape) s;
            int n = 0;
            for (int i = 0; i < m.getShapeCount(); i++) {
                n += outlineLength(m.getShape(i));
            }
            return n;
        }
        return 2;
    }

    private int writeOutline(Shape s, float[] out, int at) {
        if (s instanceof Polygon) {
            Polygon p = (Polygon) s;
            for (int i = 0; i < p.getVertexCount(); i++) {
                out[at++] = toWorldX(p.getVertexX(i), p.getVertexY(i));
                out[at++] = toWorldY(p.getVertexX(i), p.getVertexY(i));
            }
            return at;
        }
        if (s instanceof MultiShape) {
            MultiShape m = (MultiShape) s;
            for (int i = 0; i < m.getShapeCount(); i++) {
                at = writeOutline(m.getShape(i), out, at);
            }
            return at;
        }
        Circle c = (Circle) s;
        float lx = c.getCenterX() + c.getRadius();
        float ly = c.getCenterY();
        out[at++] = toWorldX(lx, ly);
        out[at++] = toWorldY(lx, ly);
        return at;
    }

    /**
     * The id the world gave this body when it was added (unique within that world), or −1.
     *
     * @return the id
     */
    public int getId() {
        return id;
    }

    /**
     * The world this body belongs to (an {@code org.emini.world.World}, seen as the physics it runs).
     *
     * @return the world, or null when the body has not been added to one
     */
    public Simulation getWorld() {
        return world;
    }

    /**
     * The body's shape.
     *
     * @return the shape
     */
    public Shape getShape() {
        return shape;
    }

    /**
     * Replaces the shape; contacts are recomputed on the next tick.
     *
     * @param shape the new shape
     */
    public void setShape(Shape shape) {
        Check.notNull("Body.setShape", "shape", shape);
        if (world != null) {
            world.solver.checkNotSolving("Body.setShape");
        }
        this.shape = shape;
        if (world != null) {
            world.bodyShapeChanged(this);
        }
    }

    /**
     * The x position of the body's origin.
     *
     * @return x (px)
     */
    public float getX() {
        return x;
    }

    /**
     * The y position of the body's origin (y points down the screen).
     *
     * @return y (px)
     */
    public float getY() {
        return y;
    }

    /**
     * Moves the body. Velocities are kept.
     *
     * @param x the new x (px)
     * @param y the new y (px)
     */
    public void setPosition(float x, float y) {
        Check.finite("Body.setPosition", "x", x);
        Check.finite("Body.setPosition", "y", y);
        if (world != null) {
            world.solver.checkNotSolving("Body.setPosition");
        }
        this.x = x;
        this.y = y;
        if (world != null) {
            world.sleep.wake(this);
            world.proxies.geometryChanged(this);
        }
    }

    /**
     * Moves the body by an offset.
     *
     * @param dx the x offset (px)
     * @param dy the y offset (px)
     */
    public void translate(float dx, float dy) {
        setPosition(x + Check.finite("Body.translate", "dx", dx), y + Check.finite("Body.translate", "dy", dy));
    }

    /**
     * The body's angle, accumulated over its whole motion (not wrapped).
     *
     * @return the angle in radians
     */
    public float getAngle() {
        return angle;
    }

    /**
     * Cosine of the body's angle, as the engine uses it.
     *
     * @return cos(angle)
     */
    public float getCos() {
        return c;
    }

    /**
     * Sine of the body's angle, as the engine uses it.
     *
     * @return sin(angle)
     */
    public float getSin() {
        return s;
    }

    /**
     * Sets the body's angle.
     *
     * @param radians the angle in radians
     */
    public void setAngle(float radians) {
        Check.finite("Body.setAngle", "radians", radians);
        if (world != null) {
            world.solver.checkNotSolving("Body.setAngle");
        }
        angle = radians;
        c = EMath.cos(radians);
        s = EMath.sin(radians);
        if (world != null) {
            world.sleep.wake(this);
            world.proxies.geometryChanged(this);
        }
    }

    /**
     * Sets the body's angle in degrees (the original engine's {@code setRotationDeg}).
     *
     * @param degrees the angle in degrees
     */
    public void setAngleDegrees(float degrees) {
        setAngle(Check.finite("Body.setAngleDegrees", "degrees", degrees) * (EMath.PI / 180f));
    }

    /**
     * The x component of the linear velocity.
     *
     * @return vx (px/s)
     */
    public float getVelocityX() {
        return vx;
    }

    /**
     * The y component of the linear velocity.
     *
     * @return vy (px/s)
     */
    public float getVelocityY() {
        return vy;
    }

    /**
     * Sets the linear velocity of a dynamic or kinematic body. A kinematic body keeps it until it
     * is set again; a dynamic one starts from it.
     *
     * @param vx the x component (px/s)
     * @param vy the y component (px/s)
     * @throws IllegalStateException when the body is static and the velocity is not zero: a static
     *     body never moves (make it kinematic to move it by a velocity); zero is accepted, as it is
     *     the static body's velocity
     */
    public void setVelocity(float vx, float vy) {
        Check.finite("Body.setVelocity", "vx", vx);
        Check.finite("Body.setVelocity", "vy", vy);
        if (!dynamic && !kinematic) {
            if (vx != 0f || vy != 0f) {
                throw new IllegalStateException("Body.setVelocity: " + this + " cannot move; a velocity of (" + vx + ", "
                    + vy + ") px/s needs a kinematic body (setKinematic(true)) or a dynamic one (setDynamic(true))");
            }
            return;
        }
        this.vx = vx;
        this.vy = vy;
        if (world != null) {
            world.sleep.wake(this);
            world.solver.velocitySet(this);
        }
    }

    /**
     * The angular velocity; positive values grow the angle.
     *
     * @return ω (rad/s)
     */
    public float getAngularVelocity() {
        return w;
    }

    /**
     * Sets the angular velocity of a dynamic or kinematic body (ignored for a body that may not
     * rotate).
     *
     * @param omega ω (rad/s)
     * @throws IllegalStateException when the body is static and ω is not zero (see
     *     {@link #setVelocity(float, float)})
     */
    public void setAngularVelocity(float omega) {
        Check.finite("Body.setAngularVelocity", "omega", omega);
        if (!dynamic && !kinematic && omega != 0f) {
            throw new IllegalStateException("Body.setAngularVelocity: " + this + " cannot turn; an angular velocity of "
                + omega + " rad/s needs a kinematic body (setKinematic(true)) or a dynamic one (setDynamic(true))");
        }
        if ((dynamic || kinematic) && rotatable) {
            w = omega;
            if (world != null) {
                world.sleep.wake(this);
                world.solver.velocitySet(this);
            }
        }
    }

    /**
     * The velocity of a world point moving with the body: v + ω × r.
     *
     * @param px the point's x (px)
     * @param py the point's y (px)
     * @return the x component (px/s)
     */
    public float getPointVelocityX(float px, float py) {
        return vx - w * (py - y);
    }

    /**
     * The velocity of a world point moving with the body: v + ω × r.
     *
     * @param px the point's x (px)
     * @param py the point's y (px)
     * @return the y component (px/s)
     */
    public float getPointVelocityY(float px, float py) {
        return vy + w * (px - x);
    }

    /**
     * Maps a body-local point to world x.
     *
     * @param lx local x (px)
     * @param ly local y (px)
     * @return world x (px)
     */
    public float toWorldX(float lx, float ly) {
        return x + c * lx - s * ly;
    }

    /**
     * Maps a body-local point to world y.
     *
     * @param lx local x (px)
     * @param ly local y (px)
     * @return world y (px)
     */
    public float toWorldY(float lx, float ly) {
        return y + s * lx + c * ly;
    }

    /**
     * Maps a world point to body-local x.
     *
     * @param wx world x (px)
     * @param wy world y (px)
     * @return local x (px)
     */
    public float toLocalX(float wx, float wy) {
        return c * (wx - x) + s * (wy - y);
    }

    /**
     * Maps a world point to body-local y.
     *
     * @param wx world x (px)
     * @param wy world y (px)
     * @return local y (px)
     */
    public float toLocalY(float wx, float wy) {
        return -s * (wx - x) + c * (wy - y);
    }

    /**
     * The body's mass: the shape's mass for a dynamic body, infinite for a static or kinematic one.
     *
     * @return the mass
     */
    public float getMass() {
        return dynamic ? shape.getMass() : Float.POSITIVE_INFINITY;
    }

    /**
     * The inverse mass the solver uses (0 for static and kinematic bodies).
     *
     * @return 1/mass, or 0
     */
    public float getInverseMass() {
        return dynamic ? shape.getInverseMass() : 0f;
    }

    /**
     * The moment of inertia about the body's origin (infinite when static, kinematic or not rotatable).
     *
     * @return the inertia (mass·px²)
     */
    public float getInertia() {
        return dynamic && rotatable ? shape.getInertia() : Float.POSITIVE_INFINITY;
    }

    /**
     * The inverse inertia the solver uses (0 for static, kinematic or non-rotatable bodies).
     *
     * @return 1/inertia, or 0
     */
    public float getInverseInertia() {
        return dynamic && rotatable ? shape.getInverseInertia() : 0f;
    }

    /**
     * Kinetic energy ½mv² + ½Iω² (0 for static and kinematic bodies: their infinite mass puts them
     * outside any energy balance).
     *
     * @return the kinetic energy (mass·px²/s²)
     */
    public float getKineticEnergy() {
        if (!dynamic) {
            return 0f;
        }
        float e = 0.5f * shape.getMass() * (vx * vx + vy * vy);
        if (rotatable) {
            e += 0.5f * shape.getInertia() * w * w;
        }
        return e;
    }

    /**
     * Whether the body is dynamic: moved by gravity, contacts, constraints and forces.
     *
     * @return true when dynamic (false for static and kinematic bodies)
     */
    public boolean isDynamic() {
        return dynamic;
    }

    /**
     * Whether the body is kinematic: moved by the velocity the application sets alone.
     *
     * @return true when kinematic
     */
    public boolean isKinematic() {
        return kinematic;
    }

    /**
     * Whether the body is static: neither dynamic nor kinematic.
     *
     * @return true when static
     */
    public boolean isStatic() {
        return !dynamic && !kinematic;
    }

    /**
     * Makes the body dynamic, or static. A body made static loses its velocity; a kinematic body
     * made dynamic keeps it.
     *
     * @param dynamic true for dynamic, false for static
     */
    public void setDynamic(boolean dynamic) {
        setKind("Body.setDynamic", dynamic, false);
    }

    /**
     * Makes the body kinematic, or static. A kinematic body moves by its velocity (px/s) and
     * angular velocity (rad/s), which only the application changes ({@link #setVelocity},
     * {@link #setAngularVelocity}), every tick it is simulated (inside the simulation area, if one
     * is set), whether or not anything touches it. Its mass and inertia are infinite; gravity,
     * damping, forces and impulses do not act on it. It pushes dynamic bodies and is not pushed; a
     * body resting on it is carried by friction. It collides with dynamic bodies only: static and
     * kinematic bodies and the landscape do not stop it. A dynamic body made kinematic keeps its
     * velocity. {@code setKinematic(false)} makes a kinematic body static (it loses its velocity)
     * and leaves a static or dynamic body as it is.
     *
     * <pre>{@code
     * Body platform = new Body(0f, 300f, Shape.createRectangle(200f, 20f), false);
     * platform.setKinematic(true);
     * platform.setVelocity(50f, 0f); // 50 px/s to the right, until set again
     * world.addBody(platform);
     * }</pre>
     *
     * @param kinematic true for kinematic; false makes a kinematic body static
     */
    public void setKinematic(boolean kinematic) {
        if (kinematic || this.kinematic) {
            setKind("Body.setKinematic", false, kinematic);
        }
    }

    private void setKind(String where, boolean dynamic, boolean kinematic) {
        if (world != null) {
            world.solver.checkNotSolving(where);
        }
        this.dynamic = dynamic;
        this.kinematic = kinematic;
        if (!dynamic && !kinematic) {
            vx = 0f;
            vy = 0f;
            w = 0f;
        }
        if (world != null) {
            world.sleep.wake(this);
            world.proxies.filterChanged(this);
        }
    }

    /**
     * Whether the body may rotate.
     *
     * @return true when rotatable (the default)
     */
    public boolean canRotate() {
        return rotatable;
    }

    /**
     * Allows or forbids rotation; a body that may not rotate has infinite inertia.
     *
     * @param rotatable true to allow rotation
     */
    public void setRotatable(boolean rotatable) {
        this.rotatable = rotatable;
        if (!rotatable) {
            w = 0f;
        }
        if (world != null) {
            world.sleep.wake(this);
            world.solver.forcesChanged(this);
            world.sleep.wake(this);
            world.solver.velocitySet(this);
        }
    }

    /**
     * Whether the body collides with other bodies.
     *
     * @return true when interacting (the default)
     */
    public boolean isInteracting() {
        return interacting;
    }

    /**
     * Lets the body collide with other bodies or pass through them.
     *
     * @param interacting true to collide
     */
    public void setInteracting(boolean interacting) {
        this.interacting = interacting;
        if (world != null) {
            world.sleep.wake(this);
            world.proxies.filterChanged(this);
        }
    }

    /**
     * Whether the body sleeps: it rested long enough, with the bodies it touches, to be left out of
     * the simulation until something wakes it ({@link Simulation#setSleepingEnabled}).
     *
     * @return true while sleeping
     */
    public boolean isSleeping() {
        return sleeping;
    }

    /** Wakes the body, and the bodies it sleeps with, if it sleeps. */
    public void wakeUp() {
        if (world != null) {
            world.sleep.wake(this);
        }
    }

    /**
     * Whether the body may fall asleep.
     *
     * @return true (the default) when it may
     */
    public boolean isSleepingAllowed() {
        return sleepAllowed;
    }

    /**
     * Lets the body fall asleep, or keeps it (and every body it touches) awake, as a player's body
     * should be.
     *
     * @param allowed false to keep it awake
     */
    public void setSleepingAllowed(boolean allowed) {
        sleepAllowed = allowed;
        if (!allowed) {
            wakeUp();
        }
    }

    /**
     * Whether the body is a sensor.
     *
     * @return true for a sensor
     */
    public boolean isSensor() {
        return sensor;
    }

    /**
     * Makes the body a sensor, or solid again. A sensor collides with nothing (bodies and the
     * landscape pass through it, and it through them) but reports, in each tick's
     * {@link StepData}, the bodies that began and stopped overlapping it exactly: those it would
     * collide with if solid (layers and collision switches count), other sensors excepted. It
     * costs in proportion to the bodies near it. A dynamic sensor keeps its mass and falls as
     * before; make it static to hold it still.
     *
     * @param sensor true for a sensor
     */
    public void setSensor(boolean sensor) {
        if (this.sensor == sensor) {
            return;
        }
        this.sensor = sensor;
        if (world != null) {
            world.sleep.wake(this);
            world.proxies.filterChanged(this);
            world.sensorChanged(this);
        }
    }

    /**
     * Whether gravity acts on the body.
     *
     * @return true when affected by gravity (the default)
     */
    public boolean isAffectedByGravity() {
        return gravityAffected;
    }

    /**
     * Lets gravity act on the body or not.
     *
     * @param affected true to feel gravity
     */
    public void setGravityAffected(boolean affected) {
        this.gravityAffected = affected;
        if (world != null) {
            world.sleep.wake(this);
            world.solver.forcesChanged(this);
        }
    }

    /**
     * Whether this body is swept against moving bodies too. Every fast body is already kept from
     * passing through static bodies and the landscape; a bullet is also kept from passing through
     * other dynamic bodies, at some extra cost.
     *
     * @return true for a bullet
     */
    public boolean isBullet() {
        return bullet;
    }

    /**
     * Marks the body as a bullet (see {@link #isBullet()}).
     *
     * @param bullet true for a bullet
     */
    public void setBullet(boolean bullet) {
        this.bullet = bullet;
    }

    /**
     * Adds a collision layer. Two bodies that share any layer do not collide with each other
     * (the original engine's meaning), which is how jointed bodies are kept from colliding. Layers
     * and Box2D's filter ({@link #setCategoryBits(int)}) both apply: a pair collides only when
     * neither keeps it apart.
     *
     * @param layer the layer, 0 to 31
     */
    public void addCollisionLayer(int layer) {
        setCollisionLayers(layers | (1 << checkLayer("Body.addCollisionLayer", layer)));
    }

    /**
     * Removes a collision layer.
     *
     * @param layer the layer, 0 to 31
     */
    public void removeCollisionLayer(int layer) {
        setCollisionLayers(layers & ~(1 << checkLayer("Body.removeCollisionLayer", layer)));
    }

    /**
     * The collision layers as a bit set (bit k set when layer k is on).
     *
     * @return the layer bits
     */
    public int getCollisionLayers() {
        return layers;
    }

    /**
     * Sets all collision layers at once.
     *
     * @param bits the layer bits
     */
    public void setCollisionLayers(int bits) {
        layers = bits;
        if (world != null) {
            world.sleep.wake(this);
            world.proxies.filterChanged(this);
        }
    }

    /**
     * The categories this body belongs to, as a bit set (Box2D's {@code categoryBits}).
     *
     * @return the category bits; {@link #DEFAULT_CATEGORY_BITS} unless set
     */
    public int getCategoryBits() {
        return categoryBits;
    }

    /**
     * Sets the categories this body belongs to (Box2D's {@code categoryBits}, 32 of them). With
     * Box2D's rule, two bodies A and B collide when they share a positive group index, never when
     * they share a negative one, and otherwise when each one's mask holds a category of the other:
     * {@code (catA & maskB) != 0 && (catB & maskA) != 0}. The original engine's layers
     * ({@link #setCollisionLayers(int)}) apply as well: both rules must let a pair collide. The
     * defaults (category bit 0, every mask bit, group 0) keep every pair the layers allow.
     *
     * <pre>{@code
     * final int PLAYER = 1 << 1, ENEMY = 1 << 2, DEBRIS = 1 << 3;
     * player.setCategoryBits(PLAYER);
     * debris.setCategoryBits(DEBRIS);
     * debris.setMaskBits(~(PLAYER | DEBRIS)); // debris hits enemies and the level, not the player or itself
     * }</pre>
     *
     * @param bits the category bits (any int; 0 puts the body in no category, so it collides
     *     only through a shared positive group)
     */
    public void setCategoryBits(int bits) {
        categoryBits = bits;
        filterChanged();
    }

    /**
     * The categories this body collides with, as a bit set (Box2D's {@code maskBits}).
     *
     * @return the mask bits; {@link #DEFAULT_MASK_BITS} unless set
     */
    public int getMaskBits() {
        return maskBits;
    }

    /**
     * Sets the categories this body collides with (Box2D's {@code maskBits}); see
     * {@link #setCategoryBits(int)} for the rule.
     *
     * @param bits the mask bits (any int; −1, all bits, is the default)
     */
    public void setMaskBits(int bits) {
        maskBits = bits;
        filterChanged();
    }

    /**
     * The collision group (Box2D's {@code groupIndex}).
     *
     * @return the group index; 0 unless set
     */
    public int getGroupIndex() {
        return groupIndex;
    }

    /**
     * Sets the collision group (Box2D's {@code groupIndex}): bodies with the same positive group
     * always collide and bodies with the same negative group never do, whatever their categories
     * and masks (the original engine's layers, {@link Simulation#disableCollision} and the world's
     * filter callback still apply); group 0, the default, leaves the decision to categories and masks.
     *
     * @param group the group index, any int
     */
    public void setGroupIndex(int group) {
        groupIndex = group;
        filterChanged();
    }

    /**
     * Box2D's filter rule between two bodies' categories, masks and groups (see
     * {@link #setCategoryBits(int)}).
     *
     * @param a a body
     * @param b another body
     * @return true when the rule lets them collide
     */
    static boolean filterAllows(Body a, Body b) {
        if (a.groupIndex == b.groupIndex && a.groupIndex != 0) {
            return a.groupIndex > 0;
        }
        return (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
    }

    private void filterChanged() {
        if (world != null) {
            world.sleep.wake(this);
            world.proxies.filterChanged(this);
        }
    }

    private static int checkLayer(String where, int layer) {
        if (layer < 0 || layer > 31) {
            throw new IllegalArgumentException(where + ": layer must be in 0..31, was " + layer);
        }
        return layer;
    }

    /**
     * Applies a force at the centre of mass for the next tick.
     *
     * @param fx x component (mass·px/s²)
     * @param fy y component (mass·px/s²)
     */
    public void applyForce(float fx, float fy) {
        Check.finite("Body.applyForce", "fx", fx);
        Check.finite("Body.applyForce", "fy", fy);
        forcesForThisTick();
        forceX += fx;
        forceY += fy;
        if (world != null) {
            world.sleep.wake(this);
            world.solver.forcesChanged(this);
        }
    }

    /** Drops forces left from a tick that did not simulate this body. */
    private void forcesForThisTick() {
        long tick = world != null ? world.getTickCount() : forceTick;
        if (forceTick != tick) {
            forceX = 0f;
            forceY = 0f;
            torque = 0f;
            forceTick = tick;
        }
    }

    /**
     * Applies a force at a world point for the next tick; an off-centre force also makes a torque.
     *
     * @param fx x component (mass·px/s²)
     * @param fy y component (mass·px/s²)
     * @param px the point's x (px)
     * @param py the point's y (px)
     */
    public void applyForceAt(float fx, float fy, float px, float py) {
        Check.finite("Body.applyForceAt", "px", px);
        Check.finite("Body.applyForceAt", "py", py);
        float moment = finiteMoment("Body.applyForceAt", px, py, fx, fy);
        applyForce(fx, fy);
        torque += moment;
        if (world != null) {
            world.sleep.wake(this);
            world.solver.forcesChanged(this);
        }
    }

    /**
     * Applies an acceleration (a force proportional to the mass) for the next tick.
     *
     * @param ax x component (px/s²)
     * @param ay y component (px/s²)
     */
    public void applyAcceleration(float ax, float ay) {
        Check.finite("Body.applyAcceleration", "ax", ax);
        Check.finite("Body.applyAcceleration", "ay", ay);
        if (dynamic) {
            forcesForThisTick();
            float m = shape.getMass();
            forceX += m * ax;
            forceY += m * ay;
            if (world != null) {
                world.sleep.wake(this);
                world.solver.forcesChanged(this);
            }
        }
    }

    /**
     * Applies a torque for the next tick.
     *
     * @param t the torque (mass·px²/s²); positive grows the angle
     */
    public void applyTorque(float t) {
        Check.finite("Body.applyTorque", "torque", t);
        forcesForThisTick();
        torque += t;
        if (world != null) {
            world.sleep.wake(this);
            world.solver.forcesChanged(this);
        }
    }

    /**
     * Changes the velocity now by a·dt, the original's {@code applyAcceleration(a, dtFX)}: an
     * impulse m·a·dt at the centre of mass ({@link #applyImpulse}). With dt the world's timestep it
     * does in one go what {@link #applyAcceleration(float, float)} does over the tick; the manual's
     * jump gives dt = 1 s, a velocity change of a. Static bodies do not move.
     *
     * @param ax x component (px/s²)
     * @param ay y component (px/s²)
     * @param dt the time the acceleration acts (s), finite
     */
    public void applyAcceleration(float ax, float ay, float dt) {
        Check.finite("Body.applyAcceleration", "ax", ax);
        Check.finite("Body.applyAcceleration", "ay", ay);
        Check.finite("Body.applyAcceleration", "dt", dt);
        float m = shape.getMass();
        applyImpulse(m * ax * dt, m * ay * dt);
    }

    /**
     * Applies an impulse at the centre of mass now: the velocity changes at once by j/m.
     * (The original engine calls this {@code applyMomentum}.)
     *
     * @param jx x component (mass·px/s)
     * @param jy y component (mass·px/s)
     */
    public void applyImpulse(float jx, float jy) {
        Check.finite("Body.applyImpulse", "jx", jx);
        Check.finite("Body.applyImpulse", "jy", jy);
        if (dynamic) {
            float im = shape.getInverseMass();
            if (!EMath.isFinite(vx + im * jx) || !EMath.isFinite(vy + im * jy)) {
                throw new IllegalArgumentException("Body.applyImpulse: the velocity it gives, (" + (vx + im * jx) + ", "
                    + (vy + im * jy) + ") px/s, overflows a float");
            }
            vx += im * jx;
            vy += im * jy;
            if (world != null) {
                world.sleep.wake(this);
                world.solver.impulseApplied(this, im * jx, im * jy, 0f);
            }
        }
    }

    /**
     * Applies an impulse at a world point now, changing linear and angular velocity.
     *
     * @param jx x component (mass·px/s)
     * @param jy y component (mass·px/s)
     * @param px the point's x (px)
     * @param py the point's y (px)
     */
    public void applyImpulseAt(float jx, float jy, float px, float py) {
        Check.finite("Body.applyImpulseAt", "px", px);
        Check.finite("Body.applyImpulseAt", "py", py);
        float dw = dynamic && rotatable ? shape.getInverseInertia() * finiteMoment("Body.applyImpulseAt", px, py, jx, jy) : 0f;
        if (!EMath.isFinite(w + dw)) {
            throw new IllegalArgumentException("Body.applyImpulseAt: the angular velocity it gives, " + w + " + " + dw
                + " rad/s, overflows a float");
        }
        applyImpulse(jx, jy);
        if (dynamic && rotatable) {
            w += dw;
            if (world != null) {
                world.sleep.wake(this);
                world.solver.impulseApplied(this, 0f, 0f, dw);
            }
        }
    }

    /**
     * Applies an angular impulse now.
     *
     * @param impulse the angular impulse (mass·px²/s)
     */
    public void applyAngularImpulse(float impulse) {
        Check.finite("Body.applyAngularImpulse", "impulse", impulse);
        if (dynamic && rotatable) {
            float dw = shape.getInverseInertia() * impulse;
            w += dw;
            if (world != null) {
                world.sleep.wake(this);
                world.solver.impulseApplied(this, 0f, 0f, dw);
            }
        }
    }

    /**
     * Whether the world's last tick moved this body: a dynamic or kinematic body inside the
     * simulation area, or any such body without one. Static bodies, bodies frozen outside the area
     * and bodies added since the last tick stood still.
     *
     * @return true when the last tick simulated it
     */
    public boolean isSimulated() {
        return awake;
    }

    /**
     * The number of contacts (touching or about to touch) this body had in the last tick.
     *
     * @return the contact count
     */
    public int getContactCount() {
        return contactCount;
    }

    /**
     * Copies the body's contacts of the last tick into an array.
     *
     * @param out an array of at least {@link #getContactCount()} elements
     * @return the number of contacts written
     */
    public int getContacts(Contact[] out) {
        int n = 0;
        for (Contact k = contactList; k != null && n < out.length; k = k.next(this)) {
            out[n++] = k;
        }
        return n;
    }

    /**
     * The application's object attached to this body.
     *
     * @return the user data, or null
     */
    public Object getUserData() {
        return userData;
    }

    /**
     * Attaches an application object to this body.
     *
     * @param userData any object, or null
     */
    public void setUserData(Object userData) {
        this.userData = userData;
    }

    /** (p − position) × (fx, fy), refused when it overflows a float (finite inputs, an infinite moment). */
    private float finiteMoment(String where, float px, float py, float fx, float fy) {
        float moment = (px - x) * fy - (py - y) * fx;
        if (!EMath.isFinite(moment)) {
            throw new IllegalArgumentException(where + ": the moment about the body, (p - position) x (" + fx + ", " + fy
                + ") at (" + px + ", " + py + "), overflows a float");
        }
        return moment;
    }

    /** Whether a pair exclusion keeps this body from colliding with the other. */
    boolean excludes(Body other) {
        for (int i = 0; i < noCollideCount; i++) {
            if (noCollide[i] == other) {
                return true;
            }
        }
        return false;
    }

    void exclude(Body other) {
        if (excludes(other)) {
            return;
        }
        if (noCollide == null) {
            noCollide = new Body[2];
        } else if (noCollideCount == noCollide.length) {
            noCollide = java.util.Arrays.copyOf(noCollide, 2 * noCollideCount);
        }
        noCollide[noCollideCount++] = other;
    }

    void include(Body other) {
        for (int i = 0; i < noCollideCount; i++) {
            if (noCollide[i] == other) {
                noCollide[i] = noCollide[--noCollideCount];
                noCollide[noCollideCount] = null;
                return;
            }
        }
    }

    @Override
    public String toString() {
        return "Body#" + id + (dynamic ? " dynamic" : kinematic ? " kinematic" : " static") + " at (" + x + ", " + y + ")";
    }
}
