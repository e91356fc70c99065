package org.emini.harness.fuzz.world;

import java.util.HashSet;
import java.util.Set;
import org.emini.dynamics.Body;

/**
 * The pairs of bodies a joint or spring links. A link that pulls two colliding bodies into each other
 * (a spring shorter than their distance, a joint made apart) fights their contact by the recipe's own
 * design, as the manual warns; the overlap and pass-through checks leave such pairs out.
 */
final class Links {
    private final Set<Long> pairs = new HashSet<>();

    Links(FuzzWorld w) {
        for (JointRecipe j : w.recipe().joints) {
            add(w, j.a, j.b);
        }
        for (SpringRecipe s : w.recipe().springs) {
            add(w, s.a, s.b);
        }
    }

    private void add(FuzzWorld w, int a, int b) {
        Body ba = w.byId().get(a);
        Body bb = w.byId().get(b);
        if (ba != null && bb != null) {
            pairs.add(key(ba, bb));
        }
    }

    boolean linked(Body a, Body b) {
        return b != null && pairs.contains(key(a, b));
    }

    private static long key(Body a, Body b) {
        long x = Math.min(a.getId(), b.getId());
        long y = Math.max(a.getId(), b.getId());
        return x << 32 | y;
    }
}
