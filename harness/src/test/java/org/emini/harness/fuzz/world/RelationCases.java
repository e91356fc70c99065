package org.emini.harness.fuzz.world;

import static org.junit.jupiter.api.Assertions.assertNull;

/** Checks a relation on a generated world and names the world on failure. */
final class RelationCases {
    /** The seed of the relation tests' worlds. */
    static final long SEED = 20261125L;

    private RelationCases() {
    }

    static void holds(Relation relation, int index, Profile profile) {
        Recipe r = WorldGenerator.generate(SEED, index, profile);
        Violation v = relation.check(r);
        assertNull(v, () -> v + "\n  world: " + r.summary() + "\n  again: ./emini fuzz --seed " + SEED + " --only "
                + profile.name().toLowerCase() + ":" + index);
    }
}
