package org.emini.collision;

/**
 * A bounding-box tree over items that do not move, built in one go and queried many times: the
 * index of the landscape's segments.
 *
 * <p>The build splits the items at the median of their box centres along the longer side of the
 * centres' bounds, down to leaves of at most {@link #LEAF_SIZE} items, so the tree is balanced
 * whatever the input order and a query costs O(log n + items found). Nodes and items are stored
 * depth-first in flat arrays, a node's first child right after it.
 *
 * <p>The build is deterministic (ties are broken by the items' input positions) and allocates only
 * to grow its arrays; a query allocates nothing. Not thread-safe.
 */
public final class StaticAabbTree {
    /** The most items a leaf holds. */
    public static final int LEAF_SIZE = 4;

    private int itemCount;
    private float[] itemMinX = new float[0];
    private float[] itemMinY = new float[0];
    private float[] itemMaxX = new float[0];
    private float[] itemMaxY = new float[0];
    private int[] itemId = new int[0];

    // Build scratch: the permutation being partitioned and the sort key of each input item.
    private int[] order = new int[0];
    private float[] key = new float[0];

    private int nodeCount;
    private float[] nodeMinX = new float[0];
    private float[] nodeMinY = new float[0];
    private float[] nodeMaxX = new float[0];
    private float[] nodeMaxY = new float[0];
    /** A leaf's first item; an internal node's second child. */
    private int[] nodeIndex = new int[0];
    /** A leaf's item count; 0 for an internal node. */
    private int[] nodeItems = new int[0];
    private int height;

    private int[] stack = new int[64];

    /** Creates an empty tree. */
    public StaticAabbTree() {
    }

    /**
     * Replaces the tree's contents with count items, item i having the box (minX[i], minY[i],
     * maxX[i], maxY[i]) and the id ids[i]. The arrays are read, not kept.
     *
     * @param count the number of items, ≥ 0
     * @param minX left of each box
     * @param minY top of each box
     * @param maxX right of each box
     * @param maxY bottom of each box
     * @param ids the id reported for each item
     * @throws IllegalArgumentException if count is negative or exceeds an array's length
     */
    public void build(int count, float[] minX, float[] minY, float[] maxX, float[] maxY,
            int[] ids) {
        if (count < 0 || count > minX.length || count > minY.length || count > maxX.length
                || count > maxY.length || count > ids.length) {
            throw new IllegalArgumentException("StaticAabbTree.build: count " + count
                    + " is negative or exceeds an array's length");
        }
        if (order.length < count) {
            int n = Math.max(count, 2 * order.length);
            order = new int[n];
            key = new float[n];
            itemMinX = new float[n];
            itemMinY = new float[n];
            itemMaxX = new float[n];
            itemMaxY = new float[n];
            itemId = new int[n];
        }
        int maxNodes = 2 * count;
        if (nodeMinX.length < maxNodes) {
            nodeMinX = new float[maxNodes];
            nodeMinY = new float[maxNodes];
            nodeMaxX = new float[maxNodes];
            nodeMaxY = new float[maxNodes];
            nodeIndex = new int[maxNodes];
            nodeItems = new int[maxNodes];
        }
        for (int i = 0; i < count; i++) {
            order[i] = i;
        }
        itemCount = count;
        nodeCount = 0;
        height = 0;
        if (count > 0) {
            buildNode(0, count, 1, minX, minY, maxX, maxY);
        }
        // Store the items in leaf order.
        for (int i = 0; i < count; i++) {
            int k = order[i];
            itemMinX[i] = minX[k];
            itemMinY[i] = minY[k];
            itemMaxX[i] = maxX[k];
            itemMaxY[i] = maxY[k];
            itemId[i] = ids[k];
        }
        if (stack.length < height + 2) {
            stack = new int[2 * (height + 2)];
        }
    }

    private int buildNode(int lo, int hi, int depth, float[] minX, float[] minY, float[] maxX,
            float[] maxY) {
        int node = nodeCount++;
        height = Math.max(height, depth);
        float bMinX = Float.POSITIVE_INFINITY;
        float bMinY = Float.POSITIVE_INFINITY;
        float bMaxX = Float.NEGATIVE_INFINITY;
        float bMaxY = Float.NEGATIVE_INFINITY;
        float cMinX = Float.POSITIVE_INFINITY;
        float cMinY = Float.POSITIVE_INFINITY;
        float cMaxX = Float.NEGATIVE_INFINITY;
        float cMaxY = Float.NEGATIVE_INFINITY;
        for (int i = lo; i < hi; i++) {
            int k = order[i];
            bMinX = Math.min(bMinX, minX[k]);
            bMinY = Math.min(bMinY, minY[k]);
            bMaxX = Math.max(bMaxX, maxX[k]);
            bMaxY = Math.max(bMaxY, maxY[k]);
            float cx = minX[k] + maxX[k];
            float cy = minY[k] + maxY[k];
            cMinX = Math.min(cMinX, cx);
            cMinY = Math.min(cMinY, cy);
            cMaxX = Math.max(cMaxX, cx);
            cMaxY = Math.max(cMaxY, cy);
        }
        nodeMinX[node] = bMinX;
        nodeMinY[node] = bMinY;
        nodeMaxX[node] = bMaxX;
        nodeMaxY[node] = bMaxY;
        if (hi - lo <= LEAF_SIZE) {
            nodeIndex[node] = lo;
            nodeItems[node] = hi - lo;
            return node;
        }
        boolean alongX = cMaxX - cMinX >= cMaxY - cMinY;
        for (int i = lo; i < hi; i++) {
            int k = order[i];
            key[k] = alongX ? minX[k] + maxX[k] : minY[k] + maxY[k];
        }
        int mid = (lo + hi) >>> 1;
        select(lo, hi - 1, mid);
        nodeItems[node] = 0;
        buildNode(lo, mid, depth + 1, minX, minY, maxX, maxY);
        nodeIndex[node] = buildNode(mid, hi, depth + 1, minX, minY, maxX, maxY);
        return node;
    }

    /** Whether input item a sorts before b: by key, then by input position. */
    private boolean before(int a, int b) {
        return key[a] < key[b] || (key[a] == key[b] && a < b);
    }

    /** Partially sorts order[lo..hi] so that order[k] is in its sorted place (quickselect). */
    private void select(int lo, int hi, int k) {
        int[] o = order;
        while (hi > lo) {
            // Median of three as the pivot, moved to hi.
            int m = (lo + hi) >>> 1;
            if (before(o[m], o[lo])) {
                swap(m, lo);
            }
            if (before(o[hi], o[lo])) {
                swap(hi, lo);
            }
            if (before(o[m], o[hi])) {
                swap(m, hi);
            }
            int pivot = o[hi];
            int store = lo;
            for (int i = lo; i < hi; i++) {
                if (before(o[i], pivot)) {
                    swap(i, store++);
                }
            }
            swap(store, hi);
            if (store == k) {
                return;
            } else if (store < k) {
                lo = store + 1;
            } else {
                hi = store - 1;
            }
        }
    }

    private void swap(int i, int j) {
        int t = order[i];
        order[i] = order[j];
        order[j] = t;
    }

    /**
     * Reports the id of every item whose box overlaps the query box (touching counts), until the
     * callback returns false.
     *
     * @param minX the left of the box
     * @param minY the top of the box
     * @param maxX the right of the box
     * @param maxY the bottom of the box
     * @param callback receives the ids; it must not rebuild or query this tree
     */
    public void query(float minX, float minY, float maxX, float maxY, QueryCallback callback) {
        if (nodeCount == 0) {
            return;
        }
        int[] st = stack;
        int top = 0;
        st[top++] = 0;
        while (top > 0) {
            int node = st[--top];
            if (nodeMinX[node] > maxX || minX > nodeMaxX[node] || nodeMinY[node] > maxY
                    || minY > nodeMaxY[node]) {
                continue;
            }
            int n = nodeItems[node];
            if (n == 0) {
                st[top++] = nodeIndex[node];
                st[top++] = node + 1;
                continue;
            }
            for (int i = nodeIndex[node], end = i + n; i < end; i++) {
                if (itemMinX[i] <= maxX && minX <= itemMaxX[i] && itemMinY[i] <= maxY
                        && minY <= itemMaxY[i] && !callback.reportProxy(itemId[i])) {
                    return;
                }
            }
        }
    }

    /**
     * Like {@link #query}, for a box swept along a translation: reports the id of every item whose
     * box the sweep meets, pruning the subtrees it misses, until the callback returns false.
     *
     * @param sweep the swept box
     * @param callback receives the ids; it must not rebuild or query this tree
     * @return false if the callback stopped the query
     */
    public boolean querySwept(SweptBox sweep, QueryCallback callback) {
        if (nodeCount == 0) {
            return true;
        }
        int[] st = stack;
        int top = 0;
        st[top++] = 0;
        while (top > 0) {
            int node = st[--top];
            if (!sweep.meets(nodeMinX[node], nodeMinY[node], nodeMaxX[node], nodeMaxY[node])) {
                continue;
            }
            int n = nodeItems[node];
            if (n == 0) {
                st[top++] = nodeIndex[node];
                st[top++] = node + 1;
                continue;
            }
            for (int i = nodeIndex[node], end = i + n; i < end; i++) {
                if (sweep.meets(itemMinX[i], itemMinY[i], itemMaxX[i], itemMaxY[i])
                        && !callback.reportProxy(itemId[i])) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * The number of items.
     *
     * @return the count given to the last build
     */
    public int getItemCount() {
        return itemCount;
    }

    /**
     * The number of levels: 0 for an empty tree, 1 for a single leaf.
     *
     * @return the height
     */
    public int getHeight() {
        return height;
    }

    @Override
    public String toString() {
        return "StaticAabbTree[" + itemCount + " items, " + nodeCount + " nodes, height " + height
                + "]";
    }
}
