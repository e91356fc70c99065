package org.emini.harness.sweep;

import java.util.ArrayList;
import java.util.List;

/**
 * The grid a sweep covers: timesteps halving from 1/{@code fromHz} s down to 1/{@code toHz} s, and
 * iteration counts. The tightest setting (smallest timestep, most iterations) is the self-consistency
 * reference for scenes without a closed form.
 *
 * @param rates ticks per second, ascending (15, 30, ..., 960)
 * @param iterations iteration counts, ascending
 */
public record SweepGrid(List<Integer> rates, List<Integer> iterations) {
    /** The default grid: 15 to 960 ticks/s by doubling, 2, 5, 10 and 20 iterations. */
    public static final SweepGrid DEFAULT = of(15, 960, List.of(2, 5, 10, 20));

    /** Rates doubling from {@code fromHz} while not above {@code toHz}. */
    public static SweepGrid of(int fromHz, int toHz, List<Integer> iterations) {
        if (fromHz <= 0 || toHz < fromHz) {
            throw new IllegalArgumentException("rates from " + fromHz + " to " + toHz + " ticks/s");
        }
        List<Integer> rates = new ArrayList<>();
        for (int r = fromHz; r <= toHz; r *= 2) {
            rates.add(r);
        }
        return new SweepGrid(List.copyOf(rates), iterations.stream().sorted().toList());
    }

    /** The sample interval every point uses: the coarsest timestep, a whole number of ticks at every rate. */
    public double every() {
        return 1.0 / rates.get(0);
    }

    /** The tightest rate. */
    public int tightestRate() {
        return rates.get(rates.size() - 1);
    }

    /** The most iterations. */
    public int tightestIterations() {
        return iterations.get(iterations.size() - 1);
    }
}
