package org.emini.internal;

/**
 * Sorts a prefix of a long array in place: heapsort needs no scratch memory and no recursion
 * ({@code java.util.Arrays.sort} may allocate a merge buffer), so a tick that sorts allocates
 * nothing. The engine sorts int keys as longs too, so there is one sort.
 */
public final class HeapSort {
    private HeapSort() {
    }

    /**
     * Sorts a[0..n) ascending.
     *
     * @param a the array
     * @param n how many leading elements to sort
     */
    public static void sort(long[] a, int n) {
        for (int i = n / 2 - 1; i >= 0; i--) {
            siftDown(a, i, n);
        }
        for (int end = n - 1; end > 0; end--) {
            long top = a[0];
            a[0] = a[end];
            a[end] = top;
            siftDown(a, 0, end);
        }
    }

    private static void siftDown(long[] a, int i, int n) {
        long value = a[i];
        int child = 2 * i + 1;
        while (child < n) {
            if (child + 1 < n && a[child + 1] > a[child]) {
                child++;
            }
            if (a[child] <= value) {
                break;
            }
            a[i] = a[child];
            i = child;
            child = 2 * i + 1;
        }
        a[i] = value;
    }
}
