package org.emini.harness.fuzz.world;

import java.util.HashMap;
import java.util.Map;
import org.emini.dynamics.Body;
import org.emini.dynamics.Contact;
import org.emini.world.World;

/**
 * Touching bodies do not stay overlapped beyond a bound: a contact (two bodies, or a body and a
 * landscape segment) whose deepest point overlaps by more than {@link #BOUND} px in every tick for
 * {@link #PERSIST} s is a violation. Overlap is the contact's separation, measured by the engine at
 * the start of each tick on the poses the previous tick left.
 *
 * <p>Why these figures: at rest Emini's soft contacts settle 0.05–0.2 px deep (README: 0.20 px under a
 * tower of 50, 0.25 px is the oracle comparison's tolerance); an impact may push deeper for a moment
 * and is pushed out at up to 60 px/s (SolverSettings.contactPushMaxVelocity), so 0.25 s removes 15 px
 * of overlap: an overlap still deeper than 2 px after that is not a transient but a body sinking (a
 * mass ratio the solver does not hold) or stuck inside another. Not judged: pairs where neither body
 * is simulated (outside the simulation area: frozen bodies keep whatever overlap they had), and
 * contacts with one-sided (faced) landscape segments, which a body coming from the open side overlaps
 * on its way through by design until its centre has crossed (a faced floor's sinking body is still
 * caught by the pass-through check), and pairs a joint or spring links ({@link Links}: the link
 * may pull them into each other by design). Judged only in worlds of at least {@link #MIN_ITERATIONS}
 * iterations: with one or two substeps a tick, the soft contacts do not hold a pile (measured: 2–4 px
 * under a mass ratio of 1:16 at 2 iterations, a body on a 0.3-mass plank at 1); such worlds are checked
 * for everything else.
 */
final class OverlapCheck implements TickCheck {
    /** Overlap allowed (px). */
    static final double BOUND = 2.0;
    /** Fewest iterations for which the bound is judged. */
    static final int MIN_ITERATIONS = 4;
    /** How long an overlap beyond the bound may last (s). */
    static final double PERSIST = 0.25;

    private final Map<Long, Integer> deepTicks = new HashMap<>();
    private final Map<Long, Integer> seen = new HashMap<>();
    private int persistTicks;
    private Links links;

    @Override
    public void start(FuzzWorld w) {
        links = new Links(w);
        persistTicks = (int) Math.ceil(PERSIST * w.recipe().ticksPerSecond);
    }

    @Override
    public Violation afterTick(FuzzWorld w, int tick) {
        World world = w.world();
        seen.clear();
        for (int i = 0; i < world.getContactCount(); i++) {
            Contact c = world.getContact(i);
            double depth = 0;
            for (int k = 0; k < c.getPointCount(); k++) {
                depth = Math.max(depth, c.getDepth(k));
            }
            if (depth <= BOUND || links.linked(c.getBodyA(), c.getBodyB()) || c.isLandscape() && w.world().getLandscape().getFace(c.getSegment()) != 0 || !simulated(w, c.getBodyA()) && (c.isLandscape() || !simulated(w, c.getBodyB()))) {
                continue;
            }
            long key = key(c);
            int n = deepTicks.getOrDefault(key, 0) + 1;
            seen.put(key, n);
            if (n > persistTicks) {
                String other = c.isLandscape() ? "landscape segment " + c.getSegment() : w.name(c.getBodyB());
                return new Violation(ViolationKind.OVERLAP, tick, String.format(
                        "%s and %s overlap by %.3f px, deeper than %.1f px for %d ticks (%.2f s); %s at (%.4g, %.4g)",
                        w.name(c.getBodyA()), other, depth, BOUND, n, n / (double) w.recipe().ticksPerSecond,
                        w.name(c.getBodyA()), c.getBodyA().getX(), c.getBodyA().getY()));
            }
        }
        deepTicks.clear();
        deepTicks.putAll(seen);
        return null;
    }

    private static long key(Contact c) {
        long a = c.getBodyA().getId();
        long b = c.isLandscape() ? -1 - c.getSegment() : c.getBodyB().getId();
        return a * 1_000_003L + b * 31 + (c.isLandscape() ? 0 : c.getPartA() * 7L + c.getPartB());
    }

    private static boolean simulated(FuzzWorld w, Body b) {
        AreaRecipe a = w.recipe().area;
        if (!b.isDynamic() || a == null) {
            return b.isDynamic();
        }
        float[] box = new float[4];
        b.getShape().computeAabb(b.getX(), b.getY(), b.getCos(), b.getSin(), box);
        return box[2] >= a.minX && box[0] <= a.maxX && (a.range || box[3] >= a.minY && box[1] <= a.maxY);
    }
}
