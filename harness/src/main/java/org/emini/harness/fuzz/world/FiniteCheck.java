package org.emini.harness.fuzz.world;

import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.particle.ParticleEmitter;

/** Every body's pose and velocity, every constraint's force and every particle stay finite. */
final class FiniteCheck implements TickCheck {
    @Override
    public void start(FuzzWorld w) {
    }

    @Override
    public Violation afterTick(FuzzWorld w, int tick) {
        String bad = firstNonFinite(w);
        return bad == null ? null : new Violation(ViolationKind.NON_FINITE, tick, bad);
    }

    static String firstNonFinite(FuzzWorld w) {
        World world = w.world();
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            if (!finite(b.getX(), b.getY(), b.getAngle()) || !finite(b.getVelocityX(), b.getVelocityY(), b.getAngularVelocity())) {
                return w.name(b) + " at (" + b.getX() + ", " + b.getY() + ") angle " + b.getAngle() + ", velocity ("
                        + b.getVelocityX() + ", " + b.getVelocityY() + ") omega " + b.getAngularVelocity();
            }
        }
        for (int i = 0; i < world.getConstraintCount(); i++) {
            float f = world.getConstraint(i).getForce();
            if (!Float.isFinite(f)) {
                return "constraint " + i + " (" + world.getConstraint(i) + ") force " + f;
            }
        }
        for (int e = 0; e < w.emitters().size(); e++) {
            ParticleEmitter em = w.emitters().get(e);
            for (int i = 0; i < em.getParticleCount(); i++) {
                if (!finite(em.getX(i), em.getY(i), em.getVelocityX(i)) || !Float.isFinite(em.getVelocityY(i))) {
                    return "emitter " + w.recipe().emitters.get(e).id + " particle " + i + " at (" + em.getX(i) + ", "
                            + em.getY(i) + ") velocity (" + em.getVelocityX(i) + ", " + em.getVelocityY(i) + ")";
                }
            }
        }
        return null;
    }

    private static boolean finite(float a, float b, float c) {
        return Float.isFinite(a) && Float.isFinite(b) && Float.isFinite(c);
    }
}
