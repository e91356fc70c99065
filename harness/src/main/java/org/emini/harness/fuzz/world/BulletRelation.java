package org.emini.harness.fuzz.world;

import org.emini.collision.TimeOfImpact;
import org.emini.shape.Shape;

/**
 * The bullet flag changes nothing where nothing is fast, bit for bit: the world with no bullet
 * against the same world with every dynamic body a bullet, compared over the ticks before the first
 * tick in which a body is fast in the engine's own sense (it moved more than twice its core radius,
 * TimeOfImpact.coreRadius, so the fast-body pass sweeps it, and a bullet sweeps against dynamic bodies
 * too). A world with a fast body within its first 10 ticks says nothing and is skipped.
 */
final class BulletRelation implements Relation {
    @Override
    public ViolationKind kind() {
        return ViolationKind.BULLET;
    }

    @Override
    public Profile profile() {
        return Profile.GENERAL;
    }

    @Override
    public Violation check(Recipe r) {
        Recipe plain = r.copy();
        plain.bodies.forEach(b -> b.bullet = false);
        Recipe bullets = r.copy();
        bullets.bodies.forEach(b -> b.bullet = b.dynamic);
        Trajectory a = Trajectory.run(plain, r.ticks);
        int slow = slowTicks(a);
        if (slow < 10) {
            return null;
        }
        String d = a.firstDifference(Trajectory.run(bullets, slow), slow);
        return d == null ? null : new Violation(kind(), -1, "with every dynamic body a bullet, " + d
                + " (no body was fast in the first " + slow + " ticks)");
    }

    /** Ticks before the first in which some body moved more than twice its core radius. */
    static int slowTicks(Trajectory t) {
        Recipe r = t.recipe;
        ShapeBuilder shapes = new ShapeBuilder(r);
        float[] core = new float[t.bodies()];
        float[] radius = new float[t.bodies()];
        for (int i = 0; i < core.length; i++) {
            Shape s = shapes.shape(r.bodies.get(i).shape);
            core[i] = TimeOfImpact.coreRadius(s);
            radius[i] = s.getBoundingRadius();
        }
        for (int k = 0; k < t.ticks; k++) {
            for (int i = 0; i < core.length; i++) {
                double travel = Math.abs(t.get(k + 1, i, 0) - t.get(k, i, 0)) + Math.abs(t.get(k + 1, i, 1) - t.get(k, i, 1))
                        + Math.abs(t.get(k + 1, i, 2) - t.get(k, i, 2)) * radius[i];
                if (r.bodies.get(i).dynamic && travel > 2 * core[i]) {
                    return k;
                }
            }
        }
        return t.ticks;
    }
}
