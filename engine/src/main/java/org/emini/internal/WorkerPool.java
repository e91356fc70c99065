package org.emini.internal;

import java.util.concurrent.ThreadFactory;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * Threads that share the calling thread's loops: {@link #run} splits a range into one contiguous part
 * per thread, runs the first part itself and returns when every part is done. The solver calls it many
 * times per tick (once per colour and pass), microseconds apart, so an idle worker spins a while
 * before it parks, and {@link #run} allocates nothing. Plain {@code java.util.concurrent}: it runs on
 * Android.
 *
 * <p>The split depends on the range and the thread count only; a task whose parts touch disjoint
 * data gives the same result whatever the count. A task that throws in a worker is rethrown by
 * {@link #run} on the calling thread. {@link #close} stops the threads.
 */
public final class WorkerPool {
    /** A loop body over part of a range. */
    public interface RangeTask {
        /**
         * Runs part of the range.
         *
         * @param worker 0 for the calling thread, 1 to {@code threads − 1} for the workers
         * @param from first index
         * @param to one past the last index
         */
        void run(int worker, int from, int to);
    }

    /** Spins of an idle worker before it parks: about a few tens of microseconds. */
    private static final int SPINS_BEFORE_PARK = 1 << 15;

    private final Worker[] workers;
    private final int threads;
    private final AtomicInteger pending = new AtomicInteger();
    /** Incremented once per {@link #run}; the volatile write publishes the job's fields below. */
    private volatile int epoch;
    private volatile boolean stopping;
    private volatile Throwable failure;
    private RangeTask task;
    private int begin;
    private int end;
    private int parts;

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
            workers[i] = new Worker(i + 1);
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
        if (p <= 1) {
            t.run(0, from, to);
            return;
        }
        task = t;
        begin = from;
        end = to;
        parts = p;
        // Every worker acknowledges every job, those without a part too: the next job's fields are
        // written only once no worker can still be reading this one's.
        pending.set(workers.length);
        epoch++;
        for (Worker w : workers) {
            if (w.parked) {
                LockSupport.unpark(w.thread);
            }
        }
        try {
            t.run(0, from, partEnd(from, n, p, 0));
        } finally {
            int spins = 0;
            while (pending.get() != 0) {
                if (++spins > SPINS_BEFORE_PARK) {
                    Thread.yield();
                }
            }
            task = null;
        }
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
        final int index;
        Thread thread;
        volatile boolean parked;

        Worker(int index) {
            this.index = index;
        }

        @Override
        public void run() {
            int seen = 0;
            while (true) {
                int e;
                int spins = 0;
                while ((e = epoch) == seen) {
                    if (stopping) {
                        return;
                    }
                    if (++spins > SPINS_BEFORE_PARK) {
                        parked = true;
                        // Re-read after announcing: run() reads parked after writing epoch, so one of
                        // the two sees the other's write.
                        if (epoch == seen && !stopping) {
                            LockSupport.park(this);
                        }
                        parked = false;
                        spins = 0;
                    }
                }
                seen = e;
                int p = parts;
                if (index < p) {
                    int n = end - begin;
                    try {
                        task.run(index, partEnd(begin, n, p, index - 1), partEnd(begin, n, p, index));
                    } catch (Throwable t) {
                        failure = t;
                    }
                }
                pending.decrementAndGet();
            }
        }
    }
}
