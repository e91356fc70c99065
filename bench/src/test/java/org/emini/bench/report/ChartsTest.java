package org.emini.bench.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ChartsTest {
    @Test
    void theSceneFloorShowsTheFastestBarAndHidesTheMissingOnes() {
        // The game level's 0.005 ms: under the old fixed floor of 0.01.
        assertEquals(0.001, Charts.floor(0.005), 1e-12);
        assertEquals(0.1, Charts.floor(0.234), 1e-12);
        assertEquals(1.0, Charts.floor(1.0), 1e-12);
        for (double fastest : new double[] {0.00002, 0.005, 0.1, 0.99, 1, 37.1}) {
            double floor = Charts.floor(fastest);
            assertTrue(floor <= fastest && floor > fastest / 10, fastest + " -> " + floor);
            assertTrue(floor > 1e-6, "a missing bar stands at 1e-6 and must stay hidden: " + floor);
        }
        assertEquals(0.01, Charts.floor(Double.POSITIVE_INFINITY), 0.0, "nothing measured");
        // A zero time would put the log axis at 0 (log10 of 0 is minus infinity).
        assertEquals(0.01, Charts.floor(0), 0.0, "a zero time");
        assertEquals(0.01, Charts.floor(Double.NaN), 0.0, "no figure");
    }
}
