package org.emini.harness.fuzz.world;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * The fuzz budget of {@code ./emini test}: 48 seeded worlds (every profile six times) checked against
 * every invariant, and 48 relation checks (each relation six times), without shrinking; no world may
 * violate anything. A failure lists each violation with the command that checks its world again.
 */
class WorldFuzzBudgetTest {
    static final long SEED = 1;
    static final int WORLDS = 48;

    @Test
    void noWorldViolatesAnInvariantOrRelation() {
        WorldFuzzer.Summary s = WorldFuzzer.run(new WorldFuzzer.Options(SEED, WORLDS, true, 0, null),
                new java.io.PrintStream(java.io.OutputStream.nullOutputStream()));
        String found = s.findings().stream()
                .map(f -> f.violation() + "\n    world " + f.original().summary() + "\n    again: ./emini fuzz --seed " + SEED
                        + " --only " + f.original().profile.name().toLowerCase() + ":" + f.original().index)
                .collect(Collectors.joining("\n"));
        assertEquals(0, s.total(), s.total() + " violations in " + WORLDS + " worlds (" + s.counts() + "):\n" + found);
    }
}
