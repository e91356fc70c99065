package org.emini.internal;

/**
 * Disjoint sets over 0 to n − 1 (the engine's islands): each set is named by its smallest member,
 * so the roots do not depend on the order the sets were joined in. Grows but never shrinks, so
 * reuse allocates nothing.
 */
public final class UnionFind {
    private int[] parent = new int[16];

    /**
     * Makes each of 0 to n − 1 a set of its own.
     *
     * @param n the members
     */
    public void reset(int n) {
        if (parent.length < n) {
            parent = new int[Math.max(n, 2 * parent.length)];
        }
        for (int i = 0; i < n; i++) {
            parent[i] = i;
        }
    }

    /**
     * The smallest member of i's set.
     *
     * @param i a member
     * @return its set's root
     */
    public int find(int i) {
        int r = i;
        while (parent[r] != r) {
            r = parent[r];
        }
        // Point the path walked at the root, so that later finds are short.
        while (parent[i] != r) {
            int up = parent[i];
            parent[i] = r;
            i = up;
        }
        return r;
    }

    /**
     * Joins the sets of a and b.
     *
     * @param a a member
     * @param b a member
     */
    public void union(int a, int b) {
        int ra = find(a);
        int rb = find(b);
        if (ra < rb) {
            parent[rb] = ra;
        } else if (rb < ra) {
            parent[ra] = rb;
        }
    }
}
