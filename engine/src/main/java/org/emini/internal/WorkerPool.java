package org.emini.internal;

import java.util.concurrent.ThreadFactory;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * Threads that share the calling thread's loops: {@link #run} splits a range into one contiguous part
 * per thread, runs the first part itself and returns when every part is done. The solver calls it many
 * times per tick (once per colour and pass), microseconds apart, so an idle worker spins a while
 * before it parks, and {@link #run} allocates nothing. Plain {@code java.util.concurrent}: it runs on
 * Android.
 *
 * <p>The parts are claimed: the calling thread takes the first, the workers take the others, and
 * once done with its own the calling thread takes whatever is left. A worker that is parked, or
 * whose core the system gave to another process, therefore never holds the tick up; on a busy
 * device the caller does all the parts alone.
 *
 * <p>The split depends on the range and the thread count only, and a task is told which part it
 * runs, not which thread runs it: a task whose parts touch disjoint data gives the same result
 * whatever the count and whichever thread takes a part. A task that throws is rethrown by
 * {@link #run} on the calling thread. {@link #close} stops the threads.
 */
public final class WorkerPool {
    /** A loop body over part of a range. */
    public interface RangeTask {
        /**
         * Runs part of the range.
         *
         * @param part the part's index, 0 to the thread count − 1 (0: the first part, which the
         *     calling thread runs); in one {@link #run} each index runs once, on one thread, so a task
         *     may keep scratch space per index
         * @param from first index
         * @param to one past the last index
         */
        void run(int part, int from, int to);
    }

    /** Spins of an idle worker before it parks: 80-90 µs on this project's machine (2026-11-29). */
    private static final int SPINS_BEFORE_PARK = 1 << 15;

    private final Worker[] workers;
    private final int threads;
    /**
     * The job's number (high 32 bits), its part count (16 bits) and its next unclaimed part (low 16
     * bits). A claim is a compare-and-set from the value read before the job's fields, so a worker that
     * read the fields of a job already finished (and perhaps half-overwritten by the next) fails its
     * claim instead of running them: while a part is unclaimed, the job is not done and its fields stay.
     */
    private final AtomicLong claim = new AtomicLong();
    /** Parts of the current job finished. */
    private final AtomicInteger done = new AtomicInteger();
    private volatile boolean stopping;
    private boolean alone;
    private volatile Throwable failure;
    private int jobs;
    private RangeTask task;
    private int begin;
    private int end;

    /**
     * Starts {@code threads − 1} worker threads.
     *
     * @param threads the threads that share a loop, counting the caller: 2 or more
     * @param factory makes the workers' threads (daemon threads named {@code emini-worker-N} when null)
     */
    public WorkerPool(int threads, ThreadFactory factory) {
        if (threads < 2) {
            throw new IllegalArgumentException("WorkerPool: threads must be at least 2, was " + threads);
        }
        this.threads = threads;
        workers = new Worker[threads - 1];
        for (int i = 0; i < workers.length; i++) {
            workers[i] = new Worker();
            Thread t = factory != null ? factory.newThread(workers[i]) : new Thread(workers[i], "emini-worker-" + (i + 1));
            if (factory == null) {
                t.setDaemon(true);
            }
            workers[i].thread = t;
        }
        for (Worker w : workers) {
            w.thread.start();
        }
    }

    /**
     * The threads that share a loop, counting the caller.
     *
     * @return at least 2
     */
    public int getThreadCount() {
        return threads;
    }

    /**
     * Runs a task over [from, to), split into at most one part per thread (fewer when the range has
     * fewer than {@code minPart} indices per thread), and returns when every part is done.
     *
     * @param t the task
     * @param from first index
     * @param to one past the last index
     * @param minPart the fewest indices worth a part of their own
     */
    public void run(RangeTask t, int from, int to, int minPart) {
        int n = to - from;
        int p = Math.min(threads, n / Math.max(1, minPart));
        if (p <= 1 || alone) {
            t.run(0, from, to);
            return;
        }
        task = t;
        begin = from;
        end = to;
        done.set(0);
        // Part 0 is the caller's from the start.
        claim.set((long) ++jobs << 32 | p << 16 | 1);
        for (Worker w : workers) {
            if (w.parked) {
                LockSupport.unpark(w.thread);
            }
        }
        runPart(t, 0, from, n, p);
        long c;
        while (nextPart(c = claim.get()) < p) {
            if (claim.compareAndSet(c, c + 1L)) {
                runPart(t, nextPart(c), from, n, p);
            }
        }
        int spins = 0;
        while (done.get() != p) {
            if (++spins > SPINS_BEFORE_PARK) {
                Thread.yield();
            }
        }
        task = null;
        Throwable f = failure;
        if (f != null) {
            failure = null;
            if (f instanceof RuntimeException) {
                throw (RuntimeException) f;
            }
            if (f instanceof Error) {
                throw (Error) f;
            }
            throw new IllegalStateException("WorkerPool: a worker failed", f);
        }
    }

    /**
     * While set, {@link #run} runs every task whole on the calling thread, and the workers park once
     * their spin ends: for ticks too small to pay for handing parts over. Called by the calling thread,
     * between runs.
     *
     * @param calling true to run alone
     */
    public void setAlone(boolean calling) {
        alone = calling;
    }

    /**
     * Whether {@link #run} runs every task whole on the calling thread (see {@link #setAlone}).
     *
     * @return true while alone
     */
    public boolean isAlone() {
        return alone;
    }

    /** Runs one part, keeps its failure for {@link #run} to rethrow, and counts it done. */
    private void runPart(RangeTask t, int part, int from, int n, int p) {
        try {
            t.run(part, partEnd(from, n, p, part - 1), partEnd(from, n, p, part));
        } catch (Throwable e) {
            failure = e;
        }
        done.incrementAndGet();
    }

    private static int nextPart(long claimed) {
        return (int) claimed & 0xFFFF;
    }

    private static int partCount(long claimed) {
        return ((int) claimed >>> 16) & 0xFFFF;
    }

    private static int partEnd(int from, int n, int p, int part) {
        return from + (int) ((long) n * (part + 1) / p);
    }

    /** Stops the workers; the pool cannot run tasks afterwards. */
    public void close() {
        stopping = true;
        for (Worker w : workers) {
            LockSupport.unpark(w.thread);
        }
    }

    private final class Worker implements Runnable {
        Thread thread;
        volatile boolean parked;

        @Override
        public void run() {
            int seen = 0;
            while (true) {
                long c;
                int spins = 0;
                while ((int) ((c = claim.get()) >>> 32) == seen) {
                    if (stopping) {
                        return;
                    }
                    if (++spins > SPINS_BEFORE_PARK) {
                        parked = true;
                        // Re-read after announcing: run() reads parked after publishing a job, so one
                        // of the two sees the other's write.
                        if ((int) (claim.get() >>> 32) == seen && !stopping) {
                            LockSupport.park(this);
                        }
                        parked = false;
                        spins = 0;
                    }
                }
                int job = (int) (c >>> 32);
                seen = job;
                int p = partCount(c);
                while (nextPart(c) < p && (int) (c >>> 32) == job) {
                    RangeTask t = task;
                    int from = begin;
                    int n = end - from;
                    if (claim.compareAndSet(c, c + 1L)) {
                        runPart(t, nextPart(c), from, n, p);
                    }
                    c = claim.get();
                }
            }
        }
    }
}
