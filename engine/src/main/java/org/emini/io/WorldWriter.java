package org.emini.io;

import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.emini.constraint.Joint;
import org.emini.constraint.Motor;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.Landscape;
import org.emini.event.Script;
import org.emini.shape.Circle;
import org.emini.shape.MultiShape;
import org.emini.shape.Polygon;
import org.emini.shape.Shape;
import org.emini.shape.ShapeSet;
import org.emini.world.World;

/**
 * Saves a {@link World} as an original world file (version 10), what the original's World Designer
 * writes and {@link WorldBuilder} loads: gravity and damping, shapes (the world's
 * {@linkplain World#getShapeSet() shape set} first, so their ids survive, then the other shapes the
 * bodies use), bodies, joints, springs, motors, the landscape and scripts (with the scripts running,
 * as rows of the script-body table), with the mapping of
 * {@code phy-mapping.md} run backwards (angular velocities and rotational motor targets negated,
 * a motor's force cap stored as the impulse per tick, values rounded to the nearest fixed-point
 * step, a circle's radius to whole pixels). String user data is stored; other user data is not.
 *
 * <p>What the format cannot hold is left out and listed in {@link #getNotSaved()}, one line each,
 * so nothing is dropped silently: the timestep and iterations, solver settings, kinematic and
 * sensor flags, collision categories, constraints other than the manual's three, events, particle
 * emitters, off-centre circles.
 *
 * <pre>{@code
 * WorldWriter writer = new WorldWriter();
 * try (OutputStream out = new FileOutputStream("level.phy")) {
 *     writer.write(world, out);
 * }
 * writer.getNotSaved();      // what the file does not hold
 * }</pre>
 */
public final class WorldWriter {
    private final List<String> notSaved = new ArrayList<String>();
    private final Map<Shape, Integer> shapeIndex = new IdentityHashMap<Shape, Integer>();
    private final Map<Body, Integer> bodyIndex = new IdentityHashMap<Body, Integer>();
    private PhyWorld doc;

    /** Creates a writer. */
    public WorldWriter() {
    }

    /**
     * Writes a world as a world file.
     *
     * @param world the world, not ticking
     * @param out where to write; not closed
     * @throws IOException when writing fails
     */
    public void write(World world, OutputStream out) throws IOException {
        new PhyWriter().write(toDocument(world), out);
    }

    /**
     * The world as a world-file document, which {@link PhyWriter} writes and
     * {@link WorldBuilder#build(PhyWorld)} builds again.
     *
     * @param world the world, not ticking
     * @return the document
     */
    public PhyWorld toDocument(World world) {
        PhyWorld.checkNotNull("WorldWriter.toDocument", "world", world);
        notSaved.clear();
        shapeIndex.clear();
        bodyIndex.clear();
        doc = new PhyWorld();
        settings(world);
        ShapeSet set = world.getShapeSet();
        for (int i = 0; i < set.getShapeCount(); i++) {
            Shape s = set.getShape(i);
            if (s != null) {
                shape(s, "shape set id " + i);
            }
        }
        // A value beyond the fixed-point range (|x| ≥ 524288) leaves its element out, listed.
        for (int i = 0; i < world.getBodyCount(); i++) {
            try {
                body(world.getBody(i), i);
            } catch (IllegalArgumentException e) {
                notSaved.add("body " + i + ": left out, " + e.getMessage());
            }
        }
        for (int i = 0; i < world.getConstraintCount(); i++) {
            try {
                constraint(world.getConstraint(i), i, world.getTimestep());
            } catch (IllegalArgumentException e) {
                notSaved.add("constraint " + i + ": left out, " + e.getMessage());
            }
        }
        landscape(world.getLandscape());
        scripts(world);
        if (world.getEventCount() > 0) {
            notSaved.add(world.getEventCount() + " events (not written yet)");
        }
        if (world.getParticleEmitterCount() > 0) {
            notSaved.add(world.getParticleEmitterCount() + " particle emitters (not written yet)");
        }
        if (world.getExternalForceCount() > 0) {
            notSaved.add(world.getExternalForceCount() + " external forces (the format has none)");
        }
        return doc;
    }

    /**
     * What the last document left out, one line each.
     *
     * @return the lines, empty when everything was saved
     */
    public List<String> getNotSaved() {
        return Collections.unmodifiableList(new ArrayList<String>(notSaved));
    }

    private void settings(World world) {
        PhyWorldSettings s = new PhyWorldSettings();
        s.setGravity(PhyVector.of(world.getGravityX(), world.getGravityY()));
        s.setDampingLinearRaw(PhyFixed.toFx(world.getDampingLateral()));
        s.setDampingRotationalRaw(PhyFixed.toFx(world.getDampingRotational()));
        userData(s, world.getUserData());
        doc.setSettings(s);
        if (world.getTimestep() != 0.05f || world.getConstraintIterations() != 10 || world.isConstraintIterationDynamic()) {
            notSaved.add("timestep " + world.getTimestep() + " s and " + world.getConstraintIterations()
                + " iterations (a loaded world has 1/20 s and 10)");
        }
    }

    /** The document's index of a shape, adding it (a multi-shape after its parts) on first use; −1 when it cannot be. */
    private int shape(Shape s, String what) {
        Integer known = shapeIndex.get(s);
        if (known != null) {
            return known;
        }
        int index;
        if (s instanceof MultiShape) {
            MultiShape m = (MultiShape) s;
            int[] parts = new int[m.getShapeCount()];
            for (int i = 0; i < parts.length; i++) {
                parts[i] = shape(m.getShape(i), what + " part " + i);
                if (parts[i] < 0) {
                    return -1;
                }
            }
            if (m.getFriction() != Shape.DEFAULT_FRICTION || m.getElasticity() != Shape.DEFAULT_ELASTICITY) {
                notSaved.add(what + ": a multi-shape's own material (the original's is the default)");
            }
            index = add(new PhyMultiShape(parts), s);
        } else {
            PhyShape p = standard(s, what);
            if (p == null) {
                return -1;
            }
            p.setMassRaw(PhyFixed.toFx(s.getMass()));
            p.setFrictionRaw(PhyFixed.toFx(s.getFriction()));
            p.setElasticityRaw(PhyFixed.toFx(s.getElasticity()));
            index = add(p, s);
        }
        return index;
    }

    private int add(PhyShapeBase p, Shape s) {
        if (doc.getShapes().size() >= PhyWorld.NONE) {
            notSaved.add(s + ": more than 255 shapes, a body cannot name it");
            return -1;
        }
        userData(p, s.getUserData());
        doc.getShapes().add(p);
        int index = doc.getShapes().size() - 1;
        shapeIndex.put(s, index);
        return index;
    }

    private PhyShape standard(Shape s, String what) {
        if (s instanceof Circle) {
            Circle c = (Circle) s;
            if (c.getCenterX() != 0f || c.getCenterY() != 0f) {
                notSaved.add(what + ": a circle off its origin (the original centres circles on it)");
                return null;
            }
            if (c.getRadius() != (float) Math.floor(c.getRadius())) {
                notSaved.add(what + ": radius " + c.getRadius() + " is truncated to " + (int) c.getRadius()
                    + " px (whole pixels in the original)");
            }
            return new PhyShape(PhyVector.of(0f, c.getRadius()));
        }
        Polygon p = (Polygon) s;
        int n = p.getVertexCount();
        PhyVector[] vs = new PhyVector[n];
        // The engine keeps counter-clockwise order (positive area); the original lists them the other way.
        for (int i = 0; i < n; i++) {
            vs[i] = PhyVector.of(p.getVertexX(n - 1 - i), p.getVertexY(n - 1 - i));
        }
        return new PhyShape(vs);
    }

    private void body(Body b, int i) {
        String what = "body " + i;
        int shape = shape(b.getShape(), what + "'s shape");
        if (shape < 0) {
            notSaved.add(what + ": left out, its shape is not saved");
            return;
        }
        if (b.isKinematic() || b.isSensor() || b.isBullet()) {
            notSaved.add(what + ": kinematic, sensor and bullet flags (saved as " + (b.isDynamic() ? "dynamic" : "static") + ")");
        }
        if (b.getCategoryBits() != Body.DEFAULT_CATEGORY_BITS || b.getMaskBits() != Body.DEFAULT_MASK_BITS
            || b.getGroupIndex() != 0) {
            notSaved.add(what + ": collision categories, mask and group (the format has layers only)");
        }
        PhyBody p = new PhyBody();
        p.setShapeIndex(shape);
        p.setPosition(PhyVector.of(b.getX(), b.getY()));
        p.setVelocity(PhyVector.of(b.getVelocityX(), b.getVelocityY()));
        float turn = 2f * (float) Math.PI;
        float angle = b.getAngle() - (float) Math.floor(b.getAngle() / turn) * turn;
        p.setAngleRaw(PhyFixed.wrapAngle2fx(PhyFixed.toFx2(angle)));
        // The original's angle grows against its angular velocity: the sign flips (phy-mapping.md).
        p.setAngularVelocityRaw(PhyFixed.toFx2(-b.getAngularVelocity()));
        p.setFlags((b.isDynamic() ? PhyBody.FLAG_DYNAMIC : 0) | (b.canRotate() ? PhyBody.FLAG_ROTATES : 0)
            | (b.isInteracting() ? 0 : PhyBody.FLAG_NOT_INTERACTING) | (b.isAffectedByGravity() ? 0 : PhyBody.FLAG_NO_GRAVITY));
        p.setCollisionLayers(b.getCollisionLayers());
        userData(p, b.getUserData());
        bodyIndex.put(b, doc.getBodies().size());
        doc.getBodies().add(p);
    }

    private void constraint(Constraint c, int i, float timestep) {
        String what = "constraint " + i + " (" + c.getClass().getSimpleName() + ")";
        PhyConstraint p;
        if (c instanceof Joint) {
            Joint j = (Joint) c;
            PhyJoint pj = new PhyJoint();
            if (!pair(pj, j.getBodyA(), j.getBodyB(), j.getLocalAnchorAX(), j.getLocalAnchorAY(), j.getLocalAnchorBX(),
                j.getLocalAnchorBY(), what)) {
                return;
            }
            pj.setFixedByte(j.isFixed() ? 1 : 0);
            if (j.getLinearHertz() != 0f || j.getAngularHertz() != 0f) {
                notSaved.add(what + ": its stiffness (the original's joints are rigid)");
            }
            p = pj;
        } else if (c instanceof Spring) {
            Spring s = (Spring) c;
            PhySpring ps = new PhySpring();
            if (!pair(ps, s.getBodyA(), s.getBodyB(), s.getLocalAnchorAX(), s.getLocalAnchorAY(), s.getLocalAnchorBX(),
                s.getLocalAnchorBY(), what)) {
                return;
            }
            ps.setRestLengthRaw(PhyFixed.toFx(s.getRestLength()));
            ps.setCoefficientRaw(PhyFixed.toFx(s.getCoefficient()));
            if (s.getDamping() != 0f || s.getFrequency() != 0f) {
                notSaved.add(what + ": damping and frequency (the original's springs have a coefficient only)");
            }
            p = ps;
        } else if (c instanceof Motor) {
            Motor m = (Motor) c;
            Integer body = bodyIndex.get(m.getBody());
            if (body == null) {
                notSaved.add(what + ": left out, its body is not saved");
                return;
            }
            PhyMotor pm = new PhyMotor();
            pm.setBody(body);
            if (m.isRotational()) {
                pm.setFlags(PhyMotor.FLAG_ROTATIONAL);
                pm.setTargetARaw(PhyFixed.toFx2(-m.getTargetAngularVelocity()));
            } else {
                pm.setFlags((m.isRelative() ? PhyMotor.FLAG_RELATIVE : 0) | (m.isOrthogonal() ? PhyMotor.FLAG_FIX_ORTHOGONAL : 0));
                pm.setTargetARaw(PhyFixed.toFx(m.getTargetVelocityX()));
                pm.setTargetBRaw(PhyFixed.toFx(m.getTargetVelocityY()));
            }
            // The original caps the impulse of a tick; the engine the force.
            float cap = m.getMaxForce() * timestep;
            pm.setMaxForceRaw(Float.isInfinite(cap) ? Integer.MAX_VALUE : PhyFixed.toFx(cap));
            p = pm;
        } else {
            notSaved.add(what + ": the format holds only the manual's joints, springs and motors");
            return;
        }
        userData(p, c.getUserData());
        doc.getConstraints().add(p);
    }

    /** The world's scripts, and its running scripts as script-body rows (a row starts at the first element). */
    private void scripts(World world) {
        Map<Script, Integer> index = new IdentityHashMap<Script, Integer>();
        for (int i = 0; i < world.getScriptCount() && i < PhyWorld.NONE; i++) {
            try {
                doc.getScripts().add(ScriptMapping.stored(world.getScript(i)));
                index.put(world.getScript(i), doc.getScripts().size() - 1);
            } catch (IllegalArgumentException e) {
                notSaved.add("script " + i + ": left out, " + e.getMessage());
            }
        }
        if (world.getScriptCount() > PhyWorld.NONE) {
            notSaved.add((world.getScriptCount() - PhyWorld.NONE) + " scripts beyond the 255 a row names");
        }
        for (int i = 0; i < world.getRunningScriptCount(); i++) {
            Integer script = index.get(world.getRunningScript(i));
            Integer body = bodyIndex.get(world.getRunningScriptBody(i));
            if (script == null || body == null || body >= PhyWorld.NONE) {
                notSaved.add("running script " + i + ": left out, its script or body is not saved");
                continue;
            }
            doc.getScriptBindings().add(new PhyScriptBinding(script, body));
        }
        if (world.getRunningScriptCount() > 0) {
            notSaved.add(world.getRunningScriptCount() + " running scripts are saved as starting again from their first element");
        }
    }

    private boolean pair(PhyPairConstraint p, Body a, Body b, float ax, float ay, float bx, float by, String what) {
        Integer ia = bodyIndex.get(a);
        Integer ib = bodyIndex.get(b);
        if (ia == null || ib == null || ia >= PhyWorld.NONE || ib >= PhyWorld.NONE) {
            notSaved.add(what + ": left out, a body of it is not saved or beyond the 255 a reference names");
            return false;
        }
        p.setBody1(ia);
        p.setAnchor1(PhyVector.of(ax, ay));
        p.setBody2(ib);
        p.setAnchor2(PhyVector.of(bx, by));
        return true;
    }

    private void landscape(Landscape land) {
        if (land.getSegmentCount() == 0 && land.getFriction() == Landscape.DEFAULT_FRICTION
            && land.getElasticity() == Landscape.DEFAULT_ELASTICITY) {
            return;
        }
        PhyLandscape p = new PhyLandscape();
        for (int i = 0; i < land.getSegmentCount(); i++) {
            p.getSegments().add(new PhySegment(PhyVector.of(land.getStartX(i), land.getStartY(i)),
                PhyVector.of(land.getEndX(i), land.getEndY(i)), land.getFace(i)));
        }
        p.getMaterial().setFrictionRaw(PhyFixed.toFx(land.getFriction()));
        p.getMaterial().setElasticityRaw(PhyFixed.toFx(land.getElasticity()));
        doc.setLandscape(p);
    }

    private static void userData(PhyElement e, Object data) {
        if (data instanceof CharSequence) {
            e.setUserData(data.toString());
        }
    }
}
