package org.emini.harness.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

class LogLogSlopeTest {
    @Test
    void aPowerLawGivesItsExponent() {
        LogLogSlope linear = new LogLogSlope();
        LogLogSlope quadratic = new LogLogSlope();
        LogLogSlope nLogN = new LogLogSlope();
        for (double n = 100; n <= 20000; n *= 2) {
            linear.add(n, 0.004 * n);
            quadratic.add(n, 3e-6 * n * n);
            nLogN.add(n, n * Math.log(n));
        }
        assertEquals(1.0, linear.slope(), 1e-12);
        assertEquals(2.0, quadratic.slope(), 1e-12);
        // n log n over this range reads as a little above linear, which is what a benchmark's slope shows.
        assertEquals(1.147, nLogN.slope(), 0.001);
    }

    @Test
    void pointsWithoutALogarithmAreLeftOutAndOneSizeHasNoSlope() {
        LogLogSlope s = new LogLogSlope();
        s.add(100, 1);
        s.add(0, 5);
        s.add(1000, -1);
        s.add(1000, Double.NaN);
        assertNull(s.slope());
        s.add(100, 2);
        assertNull(s.slope(), "two points of the same size give no slope");
        s.add(1000, 20);
        assertEquals(Math.log(20 / Math.sqrt(2)) / Math.log(10), s.slope(), 1e-12);
    }
}
