package org.emini.harness.fuzz.world;

import org.emini.constraint.Joint;
import org.emini.constraint.Motor;
import org.emini.constraint.Spring;
import org.emini.constraint.TwoBodyConstraint;
import org.emini.dynamics.Body;
import org.emini.dynamics.Constraint;
import org.emini.dynamics.Landscape;
import org.emini.world.World;
import org.emini.particle.ParticleEmitter;

/**
 * The first structural difference between two built worlds, within a tolerance: settings, every
 * body's flags, layers, pose, velocity, mass properties, material and bounding box, every
 * constraint's kind, bodies and parameters, the landscape and the emitters' settings. Lengths may
 * differ by {@code length} px, angles by {@code length}/1000 rad after wrapping, masses and factors
 * by {@code relative} of their size, inertias also by 4·{@code length}/size of themselves (moved
 * vertices change a small shape's inertia relatively more).
 */
final class WorldDiff {
    private final double length;
    private final double relative;
    private String found;

    private WorldDiff(double length, double relative) {
        this.length = length;
        this.relative = relative;
    }

    /** The first difference, or null. */
    static String of(World a, World b, double length, double relative) {
        WorldDiff d = new WorldDiff(length, relative);
        d.compare(a, b);
        return d.found;
    }

    private void compare(World a, World b) {
        near("gravity x", a.getGravityX(), b.getGravityX(), length);
        near("gravity y", a.getGravityY(), b.getGravityY(), length);
        near("damping", a.getDampingLateral(), b.getDampingLateral(), relative);
        near("rotational damping", a.getDampingRotational(), b.getDampingRotational(), relative);
        same("timestep", a.getTimestep(), b.getTimestep());
        same("iterations", a.getConstraintIterations(), b.getConstraintIterations());
        same("body count", a.getBodyCount(), b.getBodyCount());
        for (int i = 0; found == null && i < a.getBodyCount(); i++) {
            body("body " + i, a.getBody(i), b.getBody(i));
        }
        same("constraint count", a.getConstraintCount(), b.getConstraintCount());
        for (int i = 0; found == null && i < a.getConstraintCount(); i++) {
            constraint("constraint " + i, a, a.getConstraint(i), b, b.getConstraint(i));
        }
        landscape(a.getLandscape(), b.getLandscape());
        same("emitter count", a.getParticleEmitterCount(), b.getParticleEmitterCount());
        for (int i = 0; found == null && i < a.getParticleEmitterCount(); i++) {
            emitter("emitter " + i, a, a.getParticleEmitter(i), b, b.getParticleEmitter(i));
        }
    }

    private void body(String w, Body a, Body b) {
        same(w + " dynamic", a.isDynamic(), b.isDynamic());
        same(w + " rotatable", a.canRotate(), b.canRotate());
        same(w + " interacting", a.isInteracting(), b.isInteracting());
        same(w + " gravity", a.isAffectedByGravity(), b.isAffectedByGravity());
        same(w + " bullet", a.isBullet(), b.isBullet());
        same(w + " layers", a.getCollisionLayers(), b.getCollisionLayers());
        same(w + " shape type", a.getShape().getType(), b.getShape().getType());
        near(w + " x", a.getX(), b.getX(), length);
        near(w + " y", a.getY(), b.getY(), length);
        double turn = Math.IEEEremainder(a.getAngle() - b.getAngle(), 2 * Math.PI);
        near(w + " angle", turn, 0, length / 1000);
        near(w + " vx", a.getVelocityX(), b.getVelocityX(), length);
        near(w + " vy", a.getVelocityY(), b.getVelocityY(), length);
        near(w + " omega", a.getAngularVelocity(), b.getAngularVelocity(), length / 1000);
        near(w + " mass", a.getMass(), b.getMass(), relative * a.getMass());
        // Vertices moved by up to `length` change an inertia (∝ size²) by about 2·length/size of itself.
        double size = Math.max(a.getShape().getBoundingRadius(), 1e-6);
        near(w + " inertia", a.getInertia(), b.getInertia(), Math.max(relative, 4 * length / size) * a.getInertia());
        near(w + " friction", a.getShape().getFriction(), b.getShape().getFriction(), relative);
        near(w + " elasticity", a.getShape().getElasticity(), b.getShape().getElasticity(), relative);
        float[] ba = new float[4];
        float[] bb = new float[4];
        a.getShape().computeAabb(a.getX(), a.getY(), a.getCos(), a.getSin(), ba);
        b.getShape().computeAabb(b.getX(), b.getY(), b.getCos(), b.getSin(), bb);
        for (int k = 0; k < 4; k++) {
            near(w + " bounding box", ba[k], bb[k], 2 * length);
        }
    }

    private void constraint(String w, World wa, Constraint a, World wb, Constraint b) {
        same(w + " kind", a.getClass().getSimpleName(), b.getClass().getSimpleName());
        if (found != null) {
            return;
        }
        if (a instanceof TwoBodyConstraint ta && b instanceof TwoBodyConstraint tb) {
            same(w + " body A", index(wa, ta.getBodyA()), index(wb, tb.getBodyA()));
            same(w + " body B", index(wa, ta.getBodyB()), index(wb, tb.getBodyB()));
            near(w + " anchor A x", ta.getLocalAnchorAX(), tb.getLocalAnchorAX(), length);
            near(w + " anchor A y", ta.getLocalAnchorAY(), tb.getLocalAnchorAY(), length);
            near(w + " anchor B x", ta.getLocalAnchorBX(), tb.getLocalAnchorBX(), length);
            near(w + " anchor B y", ta.getLocalAnchorBY(), tb.getLocalAnchorBY(), length);
        }
        if (a instanceof Joint ja && b instanceof Joint jb) {
            same(w + " fixed", ja.isFixed(), jb.isFixed());
        } else if (a instanceof Spring sa && b instanceof Spring sb) {
            near(w + " rest length", sa.getRestLength(), sb.getRestLength(), length);
            near(w + " stiffness", sa.getCoefficient(), sb.getCoefficient(), relative * sa.getCoefficient());
            near(w + " damping", sa.getDamping(), sb.getDamping(), relative * sa.getDamping());
        } else if (a instanceof Motor ma && b instanceof Motor mb) {
            same(w + " body", index(wa, ma.getBody()), index(wb, mb.getBody()));
            same(w + " rotational", ma.isRotational(), mb.isRotational());
            near(w + " target omega", ma.getTargetAngularVelocity(), mb.getTargetAngularVelocity(), length / 1000);
            near(w + " target vx", ma.getTargetVelocityX(), mb.getTargetVelocityX(), length);
            near(w + " target vy", ma.getTargetVelocityY(), mb.getTargetVelocityY(), length);
            near(w + " max force", ma.getMaxForce(), mb.getMaxForce(), relative * ma.getMaxForce());
        }
    }

    private void landscape(Landscape a, Landscape b) {
        same("segment count", a.getSegmentCount(), b.getSegmentCount());
        if (a.getSegmentCount() > 0) {
            near("landscape friction", a.getFriction(), b.getFriction(), relative);
            near("landscape elasticity", a.getElasticity(), b.getElasticity(), relative);
        }
        for (int i = 0; found == null && i < a.getSegmentCount(); i++) {
            near("segment " + i + " start x", a.getStartX(i), b.getStartX(i), length);
            near("segment " + i + " start y", a.getStartY(i), b.getStartY(i), length);
            near("segment " + i + " end x", a.getEndX(i), b.getEndX(i), length);
            near("segment " + i + " end y", a.getEndY(i), b.getEndY(i), length);
            same("segment " + i + " face", a.getFace(i), b.getFace(i));
        }
    }

    private void emitter(String w, World wa, ParticleEmitter a, World wb, ParticleEmitter b) {
        same(w + " body", a.getBody() == null ? -1 : index(wa, a.getBody()), b.getBody() == null ? -1 : index(wb, b.getBody()));
        same(w + " capacity", a.getMaxParticles(), b.getMaxParticles());
        same(w + " seed", a.getSeed(), b.getSeed());
        same(w + " axes fixed", a.isAxesFixed(), b.isAxesFixed());
        same(w + " collide", a.canCollide(), b.canCollide());
        float[] va = {a.getEmitX1(), a.getEmitY1(), a.getEmitX2(), a.getEmitY2(), a.getSpeed(), a.getSpeedDeviation()};
        float[] vb = {b.getEmitX1(), b.getEmitY1(), b.getEmitX2(), b.getEmitY2(), b.getSpeed(), b.getSpeedDeviation()};
        for (int k = 0; k < va.length; k++) {
            near(w + " point or speed " + k, va[k], vb[k], length);
        }
        float[] ra = {a.getCreationRate(), a.getCreationRateDeviation(), a.getLifetime(), a.getLifetimeDeviation(),
            a.getElasticity(), a.getGravityFactor(), a.getDamping(), a.getAngle(), a.getAngleDeviation()};
        float[] rb = {b.getCreationRate(), b.getCreationRateDeviation(), b.getLifetime(), b.getLifetimeDeviation(),
            b.getElasticity(), b.getGravityFactor(), b.getDamping(), b.getAngle(), b.getAngleDeviation()};
        for (int k = 0; k < ra.length; k++) {
            near(w + " setting " + k, ra[k], rb[k], relative * Math.max(1, Math.abs(ra[k])));
        }
    }

    private static int index(World w, Body b) {
        for (int i = 0; i < w.getBodyCount(); i++) {
            if (w.getBody(i) == b) {
                return i;
            }
        }
        return -1;
    }

    private void same(String what, Object a, Object b) {
        if (found == null && !a.equals(b)) {
            found = what + ": " + a + " against " + b;
        }
    }

    private void near(String what, double a, double b, double tolerance) {
        if (found == null && a != b && !(Math.abs(a - b) <= tolerance)) {
            found = what + ": " + a + " against " + b + " (tolerance " + tolerance + ")";
        }
    }
}
