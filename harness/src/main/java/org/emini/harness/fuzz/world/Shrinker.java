package org.emini.harness.fuzz.world;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Predicate;

/**
 * Delta debugging (Zeller's ddmin) over a recipe's parts: removes halves, then quarters, ... then
 * single bodies, constraints and features for as long as the world still fails, within a budget of
 * runs. The result fails and no single part of it can be removed (when the budget allowed the last
 * pass).
 */
public final class Shrinker {
    private final Predicate<Recipe> fails;
    private final int budget;
    private int runs;

    /**
     * @param fails whether a recipe still shows the violation
     * @param budget the most runs of {@code fails}
     */
    public Shrinker(Predicate<Recipe> fails, int budget) {
        this.fails = fails;
        this.budget = budget;
    }

    /** The smallest failing recipe found; the original when nothing could be removed. */
    public Recipe shrink(Recipe original) {
        List<ElementRef> kept = new ArrayList<>(RecipeEdit.parts(original));
        Set<ElementRef> removed = new HashSet<>();
        int n = 2;
        while (kept.size() >= 1 && runs < budget) {
            int chunk = Math.max(1, (kept.size() + n - 1) / n);
            boolean reduced = false;
            for (int start = 0; start < kept.size() && runs < budget; start += chunk) {
                List<ElementRef> piece = kept.subList(start, Math.min(kept.size(), start + chunk));
                Set<ElementRef> trial = new HashSet<>(removed);
                trial.addAll(piece);
                if (test(RecipeEdit.without(original, trial))) {
                    removed = trial;
                    kept = remaining(original, removed);
                    n = Math.max(n - 1, 2);
                    reduced = true;
                    break;
                }
            }
            if (!reduced) {
                if (chunk == 1) {
                    break;
                }
                n = Math.min(2 * n, kept.size());
            }
        }
        return RecipeEdit.without(original, removed);
    }

    /** Runs of the predicate so far. */
    public int runs() {
        return runs;
    }

    private boolean test(Recipe r) {
        runs++;
        try {
            return fails.test(r);
        } catch (RuntimeException e) {
            return false;
        }
    }

    /** The parts still in the recipe (a removed body takes dependent parts with it). */
    private static List<ElementRef> remaining(Recipe original, Set<ElementRef> removed) {
        Set<ElementRef> left = new HashSet<>(RecipeEdit.parts(RecipeEdit.without(original, removed)));
        List<ElementRef> kept = new ArrayList<>();
        for (ElementRef ref : RecipeEdit.parts(original)) {
            if (left.contains(ref)) {
                kept.add(ref);
            }
        }
        return kept;
    }
}
