package org.emini;

import java.lang.management.ManagementFactory;
import java.util.Arrays;

/**
 * Counts the bytes the current thread allocates while it runs some work (the JVM's per-thread
 * counter: a count, not a timing), in a few windows.
 *
 * <p>One window is not enough. When a method becomes hot enough for C2, the thread that asks for
 * the compilation first resolves every string constant of the method's class (HotSpot's
 * {@code CompileBroker::compile_method}), so the engine's exception messages are allocated as
 * Strings on the ticking thread, once per class, at whatever tick C2 gets to it: a few hundred
 * bytes to 2 KB at a random tick, seen with JFR as String and byte[] allocations at method entries
 * of World, Landscape, Contact and Circle, never with C1 alone or {@code -Xint}. So the work runs
 * in up to {@code windows} windows, stopping at the first that allocates nothing: an allocation of
 * the engine's own, which recurs every tick, shows in all of them.
 */
public final class AllocationWindows {
    private final long[] bytes;
    private final int count;

    private AllocationWindows(long[] bytes, int count) {
        this.bytes = bytes;
        this.count = count;
    }

    /**
     * Runs the work in up to the given number of windows, until one allocates nothing.
     *
     * @param windows the most windows, &ge; 1
     * @param work the work of one window
     * @return the bytes of each window run
     */
    public static AllocationWindows measure(int windows, Runnable work) {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        long[] bytes = new long[windows];
        int k = 0;
        do {
            long before = threads.getThreadAllocatedBytes(thread);
            long calibration = threads.getThreadAllocatedBytes(thread) - before;
            before = threads.getThreadAllocatedBytes(thread);
            work.run();
            bytes[k] = threads.getThreadAllocatedBytes(thread) - before - calibration;
        } while (bytes[k++] != 0L && k < windows);
        return new AllocationWindows(bytes, k);
    }

    /**
     * The fewest bytes a window allocated.
     *
     * @return the least count
     */
    public long least() {
        long least = Long.MAX_VALUE;
        for (int i = 0; i < count; i++) {
            least = Math.min(least, bytes[i]);
        }
        return least;
    }

    @Override
    public String toString() {
        return "bytes per window " + Arrays.toString(Arrays.copyOf(bytes, count));
    }
}
