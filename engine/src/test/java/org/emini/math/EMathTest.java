package org.emini.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** EMath in whichever flavour runs it: π and the functions to the flavour's own precision. */
class EMathTest {
    @Test
    void piIsTheNearestValueOfTheNumberType() {
        // A decimal literal of π written for float would leave the double flavour 3e-15 short.
        assertEquals(Math.PI, EMath.PI, Math.ulp(EMath.PI) / 2);
        assertEquals(2 * Math.PI, EMath.TWO_PI, Math.ulp(EMath.TWO_PI) / 2);
    }

    @Test
    void functionsAreCorrectlyRoundedToTheNumberType() {
        float x = 0.7f;
        assertEquals(Math.sqrt(x), EMath.sqrt(x), Math.ulp(EMath.sqrt(x)) / 2);
        assertEquals(StrictMath.sin(x), EMath.sin(x), Math.ulp(EMath.sin(x)) / 2);
        assertEquals(StrictMath.cos(x), EMath.cos(x), Math.ulp(EMath.cos(x)) / 2);
        assertEquals(StrictMath.atan2(x, 2f), EMath.atan2(x, 2f), Math.ulp(EMath.atan2(x, 2f)) / 2);
    }

    @Test
    void lengthDoesNotOverflowWhereItsSquareWould() {
        float big = 0.5f * Float.MAX_VALUE;
        assertEquals(big, EMath.length(0.6f * big, 0.8f * big), 1e-6f * big);
        assertEquals(5f, EMath.length(3f, -4f));
        assertTrue(EMath.isFinite(big) && !EMath.isFinite(Float.NaN) && !EMath.isFinite(Float.POSITIVE_INFINITY));
        assertFalse(EMath.isFinite(big * 4f));
    }
}
