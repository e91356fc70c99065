package org.emini.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The pool's contract: each job's range is split into parts that depend on the range and the thread
 * count only, each part runs exactly once and is told its index, a failure reaches the caller, and
 * the caller finishes a job alone when its workers never come.
 */
class WorkerPoolTest {
    /** Per index of a range, how many times a part covered it; per part index, its range. */
    private static final class Recorder implements WorkerPool.RangeTask {
        final int[] covered = new int[1000];
        final int[] partFrom = new int[64];
        final int[] partTo = new int[64];
        final Thread[] ranBy = new Thread[64];

        @Override
        public void run(int part, int from, int to) {
            partFrom[part] = from;
            partTo[part] = to;
            ranBy[part] = Thread.currentThread();
            for (int i = from; i < to; i++) {
                covered[i]++;
            }
        }
    }

    @Test
    void everyJobIsSplitByItsRangeAndThreadCountAndEachPartRunsOnce() {
        for (int threads : new int[] {2, 3, 5}) {
            WorkerPool pool = new WorkerPool(threads, null);
            try {
                Random random = new Random(threads);
                Recorder r = new Recorder();
                // Jobs of changing ranges and part counts, back to back: a worker late for one job
                // must not run the next one's parts with the last one's fields.
                for (int job = 1; job <= 20000; job++) {
                    int from = random.nextInt(200);
                    int to = from + random.nextInt(800);
                    int minPart = 1 + random.nextInt(200);
                    pool.run(r, from, to, minPart);
                    int parts = Math.min(threads, (to - from) / minPart);
                    if (parts > 1) {
                        for (int k = 0; k < parts; k++) {
                            assertEquals(from + (to - from) * k / parts, r.partFrom[k], "job " + job + ", part " + k);
                            assertEquals(from + (to - from) * (k + 1) / parts, r.partTo[k], "job " + job + ", part " + k);
                        }
                    }
                    for (int i = 0; i < r.covered.length; i++) {
                        assertEquals(i >= from && i < to ? 1 : 0, r.covered[i], "job " + job + ", index " + i);
                        r.covered[i] = 0;
                    }
                }
            } finally {
                pool.close();
            }
        }
    }

    @Test
    void aWorkerThatNeverRunsDoesNotHoldTheCallerUp() {
        // Threads that never run the pool's loop: a worker the system does not schedule.
        WorkerPool pool = new WorkerPool(3, job -> new Thread(() -> { }));
        Recorder r = new Recorder();
        Thread[] caller = new Thread[1];
        // Preemptively: the test runs on another thread, which the timeout can stop if it hangs.
        assertTimeoutPreemptively(Duration.ofSeconds(20), () -> {
            caller[0] = Thread.currentThread();
            for (int job = 0; job < 100; job++) {
                pool.run(r, 0, 900, 1);
            }
        });
        for (int k = 0; k < 3; k++) {
            assertSame(caller[0], r.ranBy[k], "part " + k);
        }
        for (int i = 0; i < 900; i++) {
            assertEquals(100, r.covered[i], "index " + i);
        }
        pool.close();
    }

    @Test
    void aPartThatFailsIsRethrownOnTheCallingThreadAndThePoolRunsOn() {
        WorkerPool pool = new WorkerPool(2, null);
        try {
            IllegalStateException boom = new IllegalStateException("boom");
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> pool.run((part, from, to) -> {
                if (part == 1) {
                    throw boom;
                }
            }, 0, 100, 1));
            assertSame(boom, e);
            Recorder r = new Recorder();
            pool.run(r, 0, 100, 1);
            for (int i = 0; i < 100; i++) {
                assertEquals(1, r.covered[i]);
            }
        } finally {
            pool.close();
        }
    }

    @Test
    void aShortRangeRunsWholeOnTheCallingThread() {
        WorkerPool pool = new WorkerPool(4, null);
        try {
            assertRunsWholeOnTheCallingThread(pool, 10, 50, 30);
        } finally {
            pool.close();
        }
    }

    @Test
    void whileAloneEveryRangeRunsWholeOnTheCallingThread() {
        WorkerPool pool = new WorkerPool(2, null);
        try {
            pool.setAlone(true);
            assertRunsWholeOnTheCallingThread(pool, 0, 1000, 1);
            pool.setAlone(false);
            Recorder split = new Recorder();
            pool.run(split, 0, 1000, 1);
            assertEquals(500, split.partTo[0]);
            assertEquals(1000, split.partTo[1]);
        } finally {
            pool.close();
        }
    }

    /** One part, index 0, covering [from, to), run by the calling thread. */
    private static void assertRunsWholeOnTheCallingThread(WorkerPool pool, int from, int to, int minPart) {
        Recorder r = new Recorder();
        pool.run(r, from, to, minPart);
        assertSame(Thread.currentThread(), r.ranBy[0]);
        assertEquals(from, r.partFrom[0]);
        assertEquals(to, r.partTo[0]);
        assertTrue(r.ranBy[1] == null, "no second part");
    }
}
