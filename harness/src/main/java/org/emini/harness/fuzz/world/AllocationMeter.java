package org.emini.harness.fuzz.world;

import java.lang.management.ManagementFactory;

/** Bytes the current thread has allocated (HotSpot's ThreadMXBean), minus the meter's own cost. */
final class AllocationMeter {
    private final com.sun.management.ThreadMXBean bean;
    private final long overhead;

    AllocationMeter() {
        java.lang.management.ThreadMXBean plain = ManagementFactory.getThreadMXBean();
        bean = plain instanceof com.sun.management.ThreadMXBean b && b.isThreadAllocatedMemorySupported() ? b : null;
        if (bean != null && !bean.isThreadAllocatedMemoryEnabled()) {
            bean.setThreadAllocatedMemoryEnabled(true);
        }
        long least = Long.MAX_VALUE;
        for (int i = 0; bean != null && i < 16; i++) {
            long a = bean.getCurrentThreadAllocatedBytes();
            least = Math.min(least, bean.getCurrentThreadAllocatedBytes() - a);
        }
        overhead = bean == null ? 0 : least;
    }

    /** Whether this JVM measures allocation. */
    boolean supported() {
        return bean != null;
    }

    /** The running total (bytes). */
    long bytes() {
        return bean == null ? 0 : bean.getCurrentThreadAllocatedBytes();
    }

    /** Bytes allocated between two readings, without the reading itself. */
    long between(long before, long after) {
        return Math.max(0, after - before - overhead);
    }
}
