package org.emini.bench.jmh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The sleep benchmark's two worlds are what it says: settled, every box asleep in one and none in the
 * other, and the sleeping pyramid stands where the awake one does (on the 20-row pyramid, 210 boxes;
 * the benchmark itself runs the ten 20-row pyramids).
 */
class SleepCostBenchmarkTest {
    @Test
    void theAsleepWorldSleepsWholeAndRestsWhereTheAwakeOneDoes() throws Exception {
        SleepCostBenchmark.Ticked awake = SleepCostBenchmark.settled("bench/pyramid-20", false);
        SleepCostBenchmark.Ticked asleep = SleepCostBenchmark.settled("bench/pyramid-20", true);
        assertEquals(0, awake.asleep());
        assertEquals(210, asleep.asleep());
        assertEquals(210, asleep.dynamic());
        double worst = 0;
        for (int i = 0; i < awake.world.getBodyCount(); i++) {
            worst = Math.max(worst, Math.hypot(awake.world.getBody(i).getX() - asleep.world.getBody(i).getX(),
                awake.world.getBody(i).getY() - asleep.world.getBody(i).getY()));
        }
        // Asleep from about 1 s, the boxes miss the awake pyramid's further creep: well under a quarter box.
        assertTrue(worst < 1, worst + " px");
        for (int k = 0; k < 60; k++) {
            asleep.world.tick();
        }
        assertEquals(210, asleep.asleep());
    }
}
