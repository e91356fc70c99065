package org.emini.internal;

import java.util.Arrays;

/**
 * Small non-negative int ids, dense in {@code [0, high)}: a new id is the most recently freed one,
 * or else the smallest never used, so the same calls give the same ids. The owner keeps what an id
 * names in arrays of its own, grown when {@link #allocate} returns an id at their length. Grows by
 * doubling and never shrinks, so ids that come and go allocate nothing once it has grown.
 */
public final class IdPool {
    private static final int NONE = -1;
    private static final int LIVE = -2;

    /** Next free id of a free id, LIVE for a live one. */
    private int[] nextFree;
    private int high;
    private int count;
    private int freeHead = NONE;

    /**
     * Creates an empty pool.
     *
     * @param capacity the ids it holds before it first grows, &gt; 0
     */
    public IdPool(int capacity) {
        nextFree = new int[capacity];
    }

    /**
     * A new id.
     *
     * @return the most recently freed id, or else {@link #high()} before the call
     */
    public int allocate() {
        int id;
        if (freeHead != NONE) {
            id = freeHead;
            freeHead = nextFree[id];
        } else {
            if (high == nextFree.length) {
                nextFree = Arrays.copyOf(nextFree, 2 * high);
            }
            id = high++;
        }
        nextFree[id] = LIVE;
        count++;
        return id;
    }

    /**
     * Frees a live id.
     *
     * @param id the id
     */
    public void free(int id) {
        nextFree[id] = freeHead;
        freeHead = id;
        count--;
    }

    /**
     * Whether an id is live.
     *
     * @param id any int
     * @return true when it was allocated and not freed since
     */
    public boolean isLive(int id) {
        return id >= 0 && id < high && nextFree[id] == LIVE;
    }

    /**
     * One more than the largest id ever allocated.
     *
     * @return the high-water mark
     */
    public int high() {
        return high;
    }

    /**
     * The live ids.
     *
     * @return their number
     */
    public int count() {
        return count;
    }

    /**
     * Checks that the free list holds exactly the ids that are not live.
     *
     * @param owner the owner's name, for the message
     * @throws IllegalStateException describing the first violation found
     */
    public void validate(String owner) {
        int free = 0;
        for (int p = freeHead; p != NONE; p = nextFree[p]) {
            if (p < 0 || p >= high || nextFree[p] == LIVE || ++free > high - count) {
                throw new IllegalStateException(owner + ": free list broken at id " + p);
            }
        }
        if (free + count != high) {
            throw new IllegalStateException(owner + ": " + free + " free ids, expected " + (high - count));
        }
    }
}
