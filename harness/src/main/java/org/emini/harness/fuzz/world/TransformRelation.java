package org.emini.harness.fuzz.world;

/**
 * A relation between a world and a transformed copy whose motion, mapped back, must stay within a
 * bound: checked on separated worlds (contacts) and smooth worlds (none) in turns.
 */
abstract class TransformRelation implements Relation {
    @Override
    public Profile profile() {
        return Profile.SEPARATED;
    }

    @Override
    public Profile profile(int turn) {
        return turn % 2 == 0 ? Profile.SEPARATED : Profile.SMOOTH;
    }

    /** Changes the copy (in place). */
    abstract void transform(Recipe copy);

    /** What the copy is, for the report. */
    abstract String label();

    /** The map back: x → sign·(x − dx), angle → sign·angle. */
    abstract int sign();

    /** The shift the map back removes (px). */
    abstract double dx();

    /** The shift the map back removes (px). */
    abstract double dy();

    /** The bound (px) for a world, given the deviation found and the ticks run. */
    abstract double bound(Recipe r, Deviation d, int ticks);

    @Override
    public Violation check(Recipe r) {
        Recipe copy = r.copy();
        transform(copy);
        Trajectory a = Trajectory.run(r, r.ticks);
        Trajectory b = Trajectory.run(copy, r.ticks);
        Deviation d = Deviation.of(a, b, sign(), dx(), dy());
        double bound = bound(r, d, Math.min(a.ticks, b.ticks));
        if (d.distance() > bound || (a.error == null) != (b.error == null)) {
            return new Violation(kind(), d.tick(), label() + ", " + d + ", bound " + String.format("%.4g", bound) + " px"
                    + (b.error != null ? "; the " + label() + " run threw " + b.error : "")
                    + (a.error != null ? "; the original run threw " + a.error : ""));
        }
        return null;
    }
}
