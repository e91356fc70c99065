package org.emini.harness.fuzz.world;

/**
 * A simulation area that holds every body changes nothing, bit for bit: the world without an area
 * against the same world with an area of ±10⁷ px (the rectangle form for even world indices, the
 * original's x range for odd), compared until a body comes within 10⁶ px of its edge (only a world
 * that blew up gets there). Bodies inside an area go
 * through the broadphase query and the area's own body list instead of the plain loop, so this
 * checks that the two paths solve the same bodies in the same order.
 */
final class SimulationAreaRelation implements Relation {
    static final float HUGE = 1e7f;

    @Override
    public ViolationKind kind() {
        return ViolationKind.SIMULATION_AREA;
    }

    @Override
    public Profile profile() {
        return Profile.GENERAL;
    }

    @Override
    public Violation check(Recipe r) {
        Recipe plain = r.copy();
        plain.area = null;
        Recipe held = r.copy();
        held.area = new AreaRecipe();
        held.area.range = r.index % 2 == 1;
        held.area.minX = -HUGE;
        held.area.minY = -HUGE;
        held.area.maxX = HUGE;
        held.area.maxY = HUGE;
        Trajectory a = Trajectory.run(plain, r.ticks);
        int inside = inside(a);
        Trajectory b = Trajectory.run(held, inside);
        String d = a.firstDifference(b, inside);
        return d == null ? null : new Violation(kind(), -1, "with an area of ±1e7 px ("
                + (held.area.range ? "x range" : "rectangle") + ") " + d);
    }

    /** Ticks before a body first comes within 10⁶ px of the area's edge. */
    private static int inside(Trajectory t) {
        for (int k = 0; k <= t.ticks; k++) {
            for (int i = 0; i < t.bodies(); i++) {
                if (!(Math.abs(t.get(k, i, 0)) < HUGE - 1e6f && Math.abs(t.get(k, i, 1)) < HUGE - 1e6f)) {
                    return Math.max(0, k - 1);
                }
            }
        }
        return t.ticks;
    }
}
