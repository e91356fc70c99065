package org.emini.harness.fuzz.world;

/**
 * A violation, found in a generated world and shrunk.
 *
 * @param violation what the original world showed
 * @param original the generated world
 * @param shrunk the smallest world found that still shows it
 * @param shrunkViolation what the shrunk world shows
 * @param shrinkRuns runs the shrinker made
 */
public record Finding(Violation violation, Recipe original, Recipe shrunk, Violation shrunkViolation, int shrinkRuns) {
    /** Shrinks a violation of a recipe (at most {@code budget} runs; 0 keeps the original). */
    public static Finding of(Violation v, Recipe r, int budget) {
        if (budget <= 0 || v.kind() == ViolationKind.BUILD) {
            return new Finding(v, r, r, v, 0);
        }
        Shrinker shrinker = new Shrinker(c -> Reproduction.find(c, v) != null, budget);
        Recipe small = shrinker.shrink(r);
        Violation again = Reproduction.find(small, v);
        if (again == null) {
            return new Finding(v, r, r, v, shrinker.runs());
        }
        if (again.tick() >= 0 && Relations.of(v.kind()) == null && v.kind() != ViolationKind.ALLOCATION) {
            // Stop the run at the tick that shows it, if it still does there.
            Recipe shorter = small.copy();
            shorter.ticks = again.tick() + 1;
            Violation there = Reproduction.find(shorter, v);
            if (there != null) {
                small = shorter;
                again = there;
            }
        }
        return new Finding(v, r, small, again, shrinker.runs());
    }
}
