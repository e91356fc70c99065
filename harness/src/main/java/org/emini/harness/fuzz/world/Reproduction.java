package org.emini.harness.fuzz.world;

import java.util.EnumSet;
import java.util.Set;

/**
 * Whether a recipe still shows a violation: the same kind (an exception: the same exception class
 * thrown from the same engine method; a relation: the same relation), for the shrinker and replays.
 */
public final class Reproduction {
    private Reproduction() {
    }

    /** The violation this recipe shows that matches {@code wanted}, or null. */
    public static Violation find(Recipe r, Violation wanted) {
        ViolationKind kind = wanted.kind();
        Relation relation = Relations.of(kind);
        if (relation != null) {
            return relation.check(r);
        }
        Set<ViolationKind> kinds = EnumSet.of(kind);
        if (kind == ViolationKind.EXCEPTION || kind == ViolationKind.NON_FINITE) {
            kinds.add(ViolationKind.EXCEPTION);
            kinds.add(ViolationKind.NON_FINITE);
        }
        Violation v = WorldCheck.run(r, kinds, r.ticks).of(kind);
        return v != null && (kind != ViolationKind.EXCEPTION || signature(v).equals(signature(wanted))) ? v : null;
    }

    /** An exception's class and the engine method that threw it, without line numbers. */
    static String signature(Violation v) {
        String m = v.message();
        int colon = m.indexOf(':');
        int at = m.indexOf(" at ");
        String where = at < 0 ? "" : m.substring(at + 4).replaceAll(":\\d+.*", "");
        return (colon < 0 ? m : m.substring(0, colon)) + " @ " + where;
    }
}
