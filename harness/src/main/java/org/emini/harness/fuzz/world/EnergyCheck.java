package org.emini.harness.fuzz.world;

import org.emini.dynamics.Body;
import org.emini.world.World;

/**
 * No energy is created in a world without energy sources (no motors, external forces, springs,
 * removals or elasticity; joints made where both bodies were) nor one-sided segments (a body passing
 * one from its open side is pushed on through once its centre has crossed, as the engine documents,
 * which adds energy by design). Energy E = Σ ½m|v|² + ½Iω² (rotatable
 * bodies) − m(g·r) (gravity-affected bodies), over the dynamic bodies. After every tick:
 *
 * <pre>E(t) − E(0) ≤ 0.02·K_max + Σ m·|g|·1 px + 10⁻⁵·|E(0)| + Σ ½m·(10⁻³ px/s)²</pre>
 *
 * <p>Why: contacts and joints only take energy out (friction, inelastic impacts, damping), so the
 * physical rise is 0. The solver may lift a body out of an overlap by position correction (soft
 * contacts push out overlap without adding velocity; the overlap bound is well under 1 px at rest),
 * which gains m·g·depth of potential energy: the 1 px term. 2% of the largest kinetic energy so far
 * covers rounding in exchanges between kinetic and potential energy at impacts (a pendulum's or a
 * sliding body's energy is conserved only to the integrator's error). 10⁻⁵·|E(0)| is float noise of
 * positions that far from the origin. The last term is every body creeping at a thousandth of a pixel
 * a second, invisible: without gravity and at rest a world's whole budget was otherwise its kinetic
 * energy, and a joint made where both bodies were, correcting its anchors' rounding, set a
 * body moving at 8·10⁻⁸ px/s, 50 times that budget (seed 3, passive:177). A launched body (dynamic
 * iterations giving a landing box (N−1)× its impact speed) gains (N−1)² times its impact energy, far
 * beyond this.
 */
final class EnergyCheck implements TickCheck {
    private double initial;
    private double kineticMax;
    private double slop;
    private double creep;
    /** A speed no one sees (px/s). */
    static final double CREEP = 1e-3;

    /** Whether the recipe has no energy sources. */
    static boolean applies(Recipe r) {
        if (r.profile == Profile.EXTREME || !r.motors.isEmpty() || !r.forces.isEmpty() || !r.springs.isEmpty()
                || !r.removals.isEmpty() || r.landscapeElasticity > 0f && !r.segments.isEmpty()) {
            return false;
        }
        for (SegmentRecipe s : r.segments) {
            if (s.face != 0) {
                return false;
            }
        }
        for (JointRecipe j : r.joints) {
            if (!j.atPoint) {
                return false;
            }
        }
        for (ShapeRecipe s : r.shapes) {
            if (s.elasticity > 0f) {
                return false;
            }
        }
        return true;
    }

    @Override
    public void start(FuzzWorld w) {
        initial = energy(w.world());
        kineticMax = kinetic(w.world());
        double g = Math.hypot(w.world().getGravityX(), w.world().getGravityY());
        slop = 0;
        creep = 0;
        for (Body b : w.bodies()) {
            if (b.isDynamic() && b.isAffectedByGravity()) {
                slop += b.getMass() * g * 1.0;
            }
            if (b.isDynamic()) {
                creep += 0.5 * b.getMass() * CREEP * CREEP;
            }
        }
    }

    @Override
    public Violation afterTick(FuzzWorld w, int tick) {
        kineticMax = Math.max(kineticMax, kinetic(w.world()));
        double e = energy(w.world());
        double bound = 0.02 * kineticMax + slop + 1e-5 * Math.abs(initial) + creep;
        if (e - initial > bound) {
            return new Violation(ViolationKind.ENERGY, tick, String.format(
                    "energy rose by %.6g from %.6g (bound %.6g = 2%% of the largest kinetic energy %.6g + m·|g|·1 px %.6g + a "
                    + "creep of 10⁻³ px/s %.3g)%s", e - initial, initial, bound, kineticMax, slop, creep, fastest(w)));
        }
        return null;
    }

    private static String fastest(FuzzWorld w) {
        Body best = null;
        double most = -1;
        for (int i = 0; i < w.world().getBodyCount(); i++) {
            Body b = w.world().getBody(i);
            double k = b.getKineticEnergy();
            if (k > most) {
                most = k;
                best = b;
            }
        }
        return best == null ? "" : String.format("; most kinetic: %s, speed %.4g px/s at (%.4g, %.4g)", w.name(best),
                Math.hypot(best.getVelocityX(), best.getVelocityY()), best.getX(), best.getY());
    }

    static double kinetic(World world) {
        double k = 0;
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            if (b.isDynamic()) {
                double v2 = (double) b.getVelocityX() * b.getVelocityX() + (double) b.getVelocityY() * b.getVelocityY();
                k += 0.5 * b.getMass() * v2;
                if (b.canRotate()) {
                    k += 0.5 * b.getInertia() * b.getAngularVelocity() * b.getAngularVelocity();
                }
            }
        }
        return k;
    }

    static double energy(World world) {
        double e = kinetic(world);
        for (int i = 0; i < world.getBodyCount(); i++) {
            Body b = world.getBody(i);
            if (b.isDynamic() && b.isAffectedByGravity()) {
                e -= b.getMass() * ((double) world.getGravityX() * b.getX() + (double) world.getGravityY() * b.getY());
            }
        }
        return e;
    }
}
