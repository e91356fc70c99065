package org.emini.collision;

import java.util.Arrays;

/**
 * A query callback that collects what a query reports (proxies, or the world's body indices) in
 * the order reported. Keep one and {@link #clear()} it before each query, so queries allocate
 * nothing once it has grown.
 */
public final class IndexList implements QueryCallback {
    private int[] index = new int[16];
    private int count;

    /** Forgets what was collected. */
    public void clear() {
        count = 0;
    }

    /** @return the number collected */
    public int count() {
        return count;
    }

    /**
     * @param i 0 to {@link #count()} − 1
     * @return the i-th index reported
     */
    public int get(int i) {
        return index[i];
    }

    @Override
    public boolean reportProxy(int reported) {
        if (count == index.length) {
            index = Arrays.copyOf(index, 2 * count);
        }
        index[count++] = reported;
        return true;
    }
}
