package org.emini.harness.fuzz;

import java.util.function.LongConsumer;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.harness.build.WorldLimits;
import org.emini.particle.ParticleEmitter;

/** Where a world's state is not finite: bodies, particles and constraint forces. */
final class WorldState {
    private WorldState() {
    }

    /** The first non-finite value, described, or null when every value is finite. */
    static String nonFinite(World w) {
        for (int i = 0; i < w.getBodyCount(); i++) {
            Body b = w.getBody(i);
            float[] v = {b.getX(), b.getY(), b.getAngle(), b.getVelocityX(), b.getVelocityY(), b.getAngularVelocity()};
            for (int k = 0; k < v.length; k++) {
                if (!Float.isFinite(v[k])) {
                    return "body " + i + " " + new String[] {"x", "y", "angle", "vx", "vy", "omega"}[k] + " = " + v[k];
                }
            }
        }
        for (int e = 0; e < w.getParticleEmitterCount(); e++) {
            ParticleEmitter em = w.getParticleEmitter(e);
            for (int i = 0; i < em.getParticleCount(); i++) {
                if (!Float.isFinite(em.getX(i)) || !Float.isFinite(em.getY(i))) {
                    return "emitter " + e + " particle " + i + " at (" + em.getX(i) + ", " + em.getY(i) + ")";
                }
            }
        }
        for (int c = 0; c < w.getConstraintCount(); c++) {
            if (!Float.isFinite(w.getConstraint(c).getForce())) {
                return "constraint " + c + " force = " + w.getConstraint(c).getForce();
            }
        }
        return null;
    }

    /**
     * Checks a freshly built world, then ticks it and checks again after each tick. The engine's guard
     * ({@code World.tick: <body> became non-finite ...}, an IllegalStateException naming the body and the
     * tick) is a clean refusal at tick time; any other exception from a tick is a crash.
     *
     * @param before run before each tick (scheduled actions), or null
     * @param after run after each tick (metrics), or null
     * @param harnessRun whether the world is run as {@code harness run} runs it, which stops a body
     *     leaving the coordinates a float resolves (WorldLimits); false for the engine on its own
     * @return a failure or a refusal, or null when the state stayed finite
     */
    static Verdict tick(World w, int ticks, LongConsumer before, Runnable after, String blameForNaN,
                        boolean harnessRun) {
        String bad = nonFinite(w);
        if (bad != null) {
            return new Verdict(Outcome.SILENT_NAN, blameForNaN, "build", bad);
        }
        for (int k = 0; k < ticks; k++) {
            try {
                if (before != null) {
                    before.accept(k);
                }
                w.tick();
                if (after != null) {
                    after.run();
                }
            } catch (IllegalStateException e) {
                // The engine's own guard: a state that left the finite numbers, named with its body and tick.
                if (String.valueOf(e.getMessage()).startsWith("World.tick: ")) {
                    return Verdict.clean("tick " + k, e.getMessage());
                }
                return Verdict.thrown(Outcome.CRASH, "tick " + k, e);
            } catch (RuntimeException | Error e) {
                return Verdict.thrown(Outcome.CRASH, "tick " + k, e);
            }
            bad = nonFinite(w);
            if (bad != null) {
                return new Verdict(Outcome.SILENT_NAN, Verdict.ENGINE, "tick " + k, bad);
            }
            int far = harnessRun ? WorldLimits.farBody(w) : -1;
            if (far >= 0) {
                return Verdict.clean("tick " + k, "body " + far + " " + WorldLimits.far(w.getBody(far)));
            }
        }
        return null;
    }
}
