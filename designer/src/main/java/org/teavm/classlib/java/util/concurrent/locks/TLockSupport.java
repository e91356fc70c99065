package org.teavm.classlib.java.util.concurrent.locks;

/**
 * {@code java.util.concurrent.locks.LockSupport} for TeaVM, whose class library has none: the engine's
 * WorkerPool refers to it, but the page runs the engine with 0 workers (one JavaScript thread), so no
 * pool is made and these are never called. TeaVM maps this class onto the JDK's name by its
 * {@code T} prefix and package, as it does its own class library.
 */
public final class TLockSupport {
    private TLockSupport() {
    }

    /**
     * Would block the calling thread: there is no other thread to wake it in the page.
     *
     * @param blocker unused
     */
    public static void park(Object blocker) {
        throw new UnsupportedOperationException("LockSupport.park: the designer runs the engine without worker threads");
    }

    /**
     * Would wake a parked thread; none can be parked in the page.
     *
     * @param thread unused
     */
    public static void unpark(Thread thread) {
        throw new UnsupportedOperationException("LockSupport.unpark: the designer runs the engine without worker threads");
    }
}
