package org.emini.dynamics;

/**
 * In-place heapsort of an int array's prefix: O(n log n), no allocation (unlike
 * {@code Arrays.sort}, which may allocate a work array for large inputs).
 */
final class IntSort {
    private IntSort() {
    }

    /** Sorts a[0..n) ascending. */
    static void sort(int[] a, int n) {
        for (int i = n / 2 - 1; i >= 0; i--) {
            siftDown(a, i, n);
        }
        for (int end = n - 1; end > 0; end--) {
            int t = a[0];
            a[0] = a[end];
            a[end] = t;
            siftDown(a, 0, end);
        }
    }

    private static void siftDown(int[] a, int i, int n) {
        int v = a[i];
        while (true) {
            int child = 2 * i + 1;
            if (child >= n) {
                break;
            }
            if (child + 1 < n && a[child + 1] > a[child]) {
                child++;
            }
            if (a[child] <= v) {
                break;
            }
            a[i] = a[child];
            i = child;
        }
        a[i] = v;
    }
}
