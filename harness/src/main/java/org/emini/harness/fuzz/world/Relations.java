package org.emini.harness.fuzz.world;

import java.util.List;

/** Every metamorphic relation, in the order the fuzzer takes turns with them. */
public final class Relations {
    private static final List<Relation> ALL = List.of(new SimulationAreaRelation(), new IdleFeaturesRelation(),
            new IterationModeRelation(), new MirrorRelation(), new TranslationRelation(), new ConvergenceRelation(),
            new FormatRelation(), new BulletRelation());

    private Relations() {
    }

    /** All relations. */
    public static List<Relation> all() {
        return ALL;
    }

    /** The relation that reports a kind, or null for an invariant's kind. */
    public static Relation of(ViolationKind kind) {
        for (Relation r : ALL) {
            if (r.kind() == kind) {
                return r;
            }
        }
        return null;
    }
}
