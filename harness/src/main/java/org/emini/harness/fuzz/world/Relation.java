package org.emini.harness.fuzz.world;

/** A metamorphic relation: two or more runs of related worlds that must agree. */
public interface Relation {
    /** The violation kind it reports. */
    ViolationKind kind();

    /** The worlds it is checked on. */
    Profile profile();

    /** The worlds it is checked on in the fuzzer's i-th turn (some relations take turns between two kinds). */
    default Profile profile(int turn) {
        return profile();
    }

    /**
     * Checks the relation on a world.
     *
     * @return the violation, or null when it holds or does not apply to this world
     */
    Violation check(Recipe r);
}
