package org.emini.collision;

import java.util.Arrays;

/**
 * A dynamic AABB tree: leaves hold boxes and an int item each, internal nodes the union of their
 * children's boxes. Leaves are inserted by the surface-area heuristic (in 2D, the perimeter) and the
 * tree is kept balanced by AVL-like rotations on the way back up from every insertion and removal,
 * so its height stays O(log n) even for sorted insertion orders (Box2D's tree, on flat arrays).
 *
 * <p>Nodes are parallel primitive arrays indexed by node id; freed nodes are reused, arrays double
 * when full, queries walk an explicit stack kept as a field, so nothing is allocated once the tree
 * has grown to the scene. The shape of the tree, and so the order in which a query reports leaves,
 * depends only on the sequence of insertions and removals: the same calls give the same results.
 * A query's callback may query again (each query uses the stack above its caller's entries).
 */
final class DynamicTree {
    static final int NULL = -1;
    private static final int INITIAL_CAPACITY = 16;

    private float[] nodeMinX = new float[INITIAL_CAPACITY];
    private float[] nodeMinY = new float[INITIAL_CAPACITY];
    private float[] nodeMaxX = new float[INITIAL_CAPACITY];
    private float[] nodeMaxY = new float[INITIAL_CAPACITY];
    /** Parent of a live node; next free node of a free one. */
    private int[] nodeParent = new int[INITIAL_CAPACITY];
    private int[] nodeChild1 = new int[INITIAL_CAPACITY];
    private int[] nodeChild2 = new int[INITIAL_CAPACITY];
    /** Leaves have height 0, free nodes -1. */
    private int[] nodeHeight = new int[INITIAL_CAPACITY];
    /** The item of a leaf, NULL for internal and free nodes. */
    private int[] nodeItem = new int[INITIAL_CAPACITY];
    private int nodeHighWater;
    private int nodeCount;
    private int freeNodeHead = NULL;
    private int root = NULL;

    private int[] stack = new int[INITIAL_CAPACITY];
    private int stackTop;

    /** Adds a leaf with this box and item; returns its node id. */
    int insert(float minX, float minY, float maxX, float maxY, int item) {
        int leaf = allocateNode();
        nodeMinX[leaf] = minX;
        nodeMinY[leaf] = minY;
        nodeMaxX[leaf] = maxX;
        nodeMaxY[leaf] = maxY;
        nodeItem[leaf] = item;
        insertLeaf(leaf);
        return leaf;
    }

    /** Removes a leaf; its node id may be reused. */
    void remove(int leaf) {
        removeLeaf(leaf);
        releaseNode(leaf);
    }

    /** Gives a leaf a new box, re-inserting it; it keeps its node id. */
    void move(int leaf, float minX, float minY, float maxX, float maxY) {
        removeLeaf(leaf);
        nodeMinX[leaf] = minX;
        nodeMinY[leaf] = minY;
        nodeMaxX[leaf] = maxX;
        nodeMaxY[leaf] = maxY;
        insertLeaf(leaf);
    }

    /** Grows a leaf's box by {@code by} on every side (shrinks when negative) without refitting; call {@link #refitAll}. */
    void inflate(int leaf, float by) {
        nodeMinX[leaf] -= by;
        nodeMinY[leaf] -= by;
        nodeMaxX[leaf] += by;
        nodeMaxY[leaf] += by;
    }

    /** Recomputes every internal box from the leaves up, one height at a time (the shape is kept). */
    void refitAll() {
        int top = 0;
        for (int node = 0; node < nodeHighWater; node++) {
            top = Math.max(top, nodeHeight[node]);
        }
        for (int height = 1; height <= top; height++) {
            for (int node = 0; node < nodeHighWater; node++) {
                if (nodeHeight[node] == height) {
                    refit(node);
                }
            }
        }
    }

    /** Translates every box by (−dx, −dy); rounding is monotonic, so internal boxes stay the unions. */
    void shift(float dx, float dy) {
        for (int i = 0; i < nodeHighWater; i++) {
            if (nodeHeight[i] >= 0) {
                nodeMinX[i] -= dx;
                nodeMinY[i] -= dy;
                nodeMaxX[i] -= dx;
                nodeMaxY[i] -= dy;
            }
        }
    }

    float minX(int node) {
        return nodeMinX[node];
    }

    float minY(int node) {
        return nodeMinY[node];
    }

    float maxX(int node) {
        return nodeMaxX[node];
    }

    float maxY(int node) {
        return nodeMaxY[node];
    }

    /** Whether a node id is a live leaf holding this item. */
    boolean holds(int node, int item) {
        return node >= 0 && node < nodeHighWater && nodeHeight[node] == 0 && nodeItem[node] == item;
    }

    /** 0 for an empty tree or a single leaf, otherwise the edges on the longest root-to-leaf path. */
    int height() {
        return root == NULL ? 0 : nodeHeight[root];
    }

    /**
     * Reports the item of every leaf whose box overlaps the given one (touching counts), in tree
     * order, until the callback returns false.
     *
     * @return false if the callback stopped the query
     */
    boolean query(float minX, float minY, float maxX, float maxY, QueryCallback callback) {
        if (root == NULL) {
            return true;
        }
        int base = stackTop;
        try {
            push(root);
            while (stackTop > base) {
                int node = stack[--stackTop];
                if (nodeMinX[node] > maxX || minX > nodeMaxX[node] || nodeMinY[node] > maxY || minY > nodeMaxY[node]) {
                    continue;
                }
                if (nodeHeight[node] > 0) {
                    push(nodeChild1[node]);
                    push(nodeChild2[node]);
                } else if (!callback.reportProxy(nodeItem[node])) {
                    return false;
                }
            }
        } finally {
            stackTop = base;
        }
        return true;
    }

    /**
     * Like {@link #query}, for a box swept along a translation: reports the item of every leaf
     * whose box the sweep meets, pruning the subtrees it misses.
     *
     * @return false if the callback stopped the query
     */
    boolean querySwept(SweptBox sweep, QueryCallback callback) {
        if (root == NULL) {
            return true;
        }
        int base = stackTop;
        try {
            push(root);
            while (stackTop > base) {
                int node = stack[--stackTop];
                if (!sweep.meets(nodeMinX[node], nodeMinY[node], nodeMaxX[node], nodeMaxY[node])) {
                    continue;
                }
                if (nodeHeight[node] > 0) {
                    push(nodeChild1[node]);
                    push(nodeChild2[node]);
                } else if (!callback.reportProxy(nodeItem[node])) {
                    return false;
                }
            }
        } finally {
            stackTop = base;
        }
        return true;
    }

    private void push(int node) {
        if (stackTop == stack.length) {
            stack = Arrays.copyOf(stack, stackTop * 2);
        }
        stack[stackTop++] = node;
    }

    // ------------------------------------------------------------------------------------------
    // Nodes

    private int allocateNode() {
        int node;
        if (freeNodeHead != NULL) {
            node = freeNodeHead;
            freeNodeHead = nodeParent[node];
        } else {
            if (nodeHighWater == nodeHeight.length) {
                growNodes();
            }
            node = nodeHighWater++;
        }
        nodeParent[node] = NULL;
        nodeChild1[node] = NULL;
        nodeChild2[node] = NULL;
        nodeHeight[node] = 0;
        nodeItem[node] = NULL;
        nodeCount++;
        return node;
    }

    private void releaseNode(int node) {
        nodeParent[node] = freeNodeHead;
        nodeChild1[node] = NULL;
        nodeChild2[node] = NULL;
        nodeHeight[node] = -1;
        nodeItem[node] = NULL;
        freeNodeHead = node;
        nodeCount--;
    }

    private void growNodes() {
        int capacity = nodeHeight.length * 2;
        nodeMinX = Arrays.copyOf(nodeMinX, capacity);
        nodeMinY = Arrays.copyOf(nodeMinY, capacity);
        nodeMaxX = Arrays.copyOf(nodeMaxX, capacity);
        nodeMaxY = Arrays.copyOf(nodeMaxY, capacity);
        nodeParent = Arrays.copyOf(nodeParent, capacity);
        nodeChild1 = Arrays.copyOf(nodeChild1, capacity);
        nodeChild2 = Arrays.copyOf(nodeChild2, capacity);
        nodeHeight = Arrays.copyOf(nodeHeight, capacity);
        nodeItem = Arrays.copyOf(nodeItem, capacity);
    }

    // ------------------------------------------------------------------------------------------
    // Insertion, removal and balance

    /**
     * Inserts a leaf whose box is set. The sibling is found by descending from the root towards
     * the child whose perimeter grows least, stopping where pairing up with the current node is
     * cheaper than any descent (the surface-area heuristic, with perimeter as area in 2D).
     */
    private void insertLeaf(int leaf) {
        if (root == NULL) {
            root = leaf;
            nodeParent[leaf] = NULL;
            return;
        }
        float minX = nodeMinX[leaf];
        float minY = nodeMinY[leaf];
        float maxX = nodeMaxX[leaf];
        float maxY = nodeMaxY[leaf];

        int index = root;
        while (nodeHeight[index] > 0) {
            int child1 = nodeChild1[index];
            int child2 = nodeChild2[index];
            float combined = unionPerimeter(index, minX, minY, maxX, maxY);
            // Cost of a new parent for this node and the leaf.
            float cost = 2f * combined;
            // Every ancestor below here also grows by this much.
            float inheritance = 2f * (combined - perimeter(index));
            float cost1 = descentCost(child1, minX, minY, maxX, maxY) + inheritance;
            float cost2 = descentCost(child2, minX, minY, maxX, maxY) + inheritance;
            if (cost < cost1 && cost < cost2) {
                break;
            }
            index = cost1 < cost2 ? child1 : child2;
        }

        int sibling = index;
        int oldParent = nodeParent[sibling];
        int newParent = allocateNode();
        nodeParent[newParent] = oldParent;
        nodeChild1[newParent] = sibling;
        nodeChild2[newParent] = leaf;
        nodeParent[sibling] = newParent;
        nodeParent[leaf] = newParent;
        if (oldParent == NULL) {
            root = newParent;
        } else if (nodeChild1[oldParent] == sibling) {
            nodeChild1[oldParent] = newParent;
        } else {
            nodeChild2[oldParent] = newParent;
        }
        refitUpwards(newParent);
    }

    /** Detaches a leaf from the tree (the leaf node itself stays allocated). */
    private void removeLeaf(int leaf) {
        if (leaf == root) {
            root = NULL;
            return;
        }
        int parent = nodeParent[leaf];
        int grandParent = nodeParent[parent];
        int sibling = nodeChild1[parent] == leaf ? nodeChild2[parent] : nodeChild1[parent];
        nodeParent[leaf] = NULL;
        releaseNode(parent);
        nodeParent[sibling] = grandParent;
        if (grandParent == NULL) {
            root = sibling;
            return;
        }
        if (nodeChild1[grandParent] == parent) {
            nodeChild1[grandParent] = sibling;
        } else {
            nodeChild2[grandParent] = sibling;
        }
        refitUpwards(grandParent);
    }

    /** Rebalances and refits every node from {@code index} up to the root. */
    private void refitUpwards(int index) {
        while (index != NULL) {
            index = balance(index);
            refit(index);
            index = nodeParent[index];
        }
    }

    /** Recomputes an internal node's box and height from its children. */
    private void refit(int node) {
        int c1 = nodeChild1[node];
        int c2 = nodeChild2[node];
        nodeMinX[node] = min(nodeMinX[c1], nodeMinX[c2]);
        nodeMinY[node] = min(nodeMinY[c1], nodeMinY[c2]);
        nodeMaxX[node] = max(nodeMaxX[c1], nodeMaxX[c2]);
        nodeMaxY[node] = max(nodeMaxY[c1], nodeMaxY[c2]);
        nodeHeight[node] = 1 + Math.max(nodeHeight[c1], nodeHeight[c2]);
    }

    /**
     * If the children's heights of {@code a} differ by more than one, rotates the taller child up
     * into a's place and returns it; otherwise returns a. The children of a must be up to date.
     */
    private int balance(int a) {
        // a's own height may be stale (a new parent), so only its children's heights are used.
        int b = nodeChild1[a];
        int c = nodeChild2[a];
        int diff = nodeHeight[c] - nodeHeight[b];
        if (diff > 1) {
            return rotateUp(a, c, true);
        }
        if (diff < -1) {
            return rotateUp(a, b, false);
        }
        return a;
    }

    /**
     * Rotates child p of a into a's place: p's taller child stays with p, a becomes p's other
     * child and takes p's shorter child in the slot where p was.
     */
    private int rotateUp(int a, int p, boolean pIsChild2) {
        int f = nodeChild1[p];
        int g = nodeChild2[p];
        int keep;
        int give;
        if (nodeHeight[f] > nodeHeight[g]) {
            keep = f;
            give = g;
        } else {
            keep = g;
            give = f;
        }
        int up = nodeParent[a];
        nodeParent[p] = up;
        if (up == NULL) {
            root = p;
        } else if (nodeChild1[up] == a) {
            nodeChild1[up] = p;
        } else {
            nodeChild2[up] = p;
        }
        nodeChild1[p] = a;
        nodeChild2[p] = keep;
        nodeParent[keep] = p;
        nodeParent[a] = p;
        if (pIsChild2) {
            nodeChild2[a] = give;
        } else {
            nodeChild1[a] = give;
        }
        nodeParent[give] = a;
        refit(a);
        refit(p);
        return p;
    }

    /** Cost of inserting the leaf box somewhere below {@code child} (excluding inheritance). */
    private float descentCost(int child, float minX, float minY, float maxX, float maxY) {
        float combined = unionPerimeter(child, minX, minY, maxX, maxY);
        // A leaf would get a new parent of this perimeter; an internal node merely grows.
        return nodeHeight[child] == 0 ? combined : combined - perimeter(child);
    }

    private float perimeter(int node) {
        return 2f * ((nodeMaxX[node] - nodeMinX[node]) + (nodeMaxY[node] - nodeMinY[node]));
    }

    private float unionPerimeter(int node, float minX, float minY, float maxX, float maxY) {
        float w = max(nodeMaxX[node], maxX) - min(nodeMinX[node], minX);
        float h = max(nodeMaxY[node], maxY) - min(nodeMinY[node], minY);
        return 2f * (w + h);
    }

    private static float min(float a, float b) {
        return a < b ? a : b;
    }

    private static float max(float a, float b) {
        return a > b ? a : b;
    }

    // ------------------------------------------------------------------------------------------
    // Validation

    /**
     * Checks the tree's invariants: parent and child links, heights, every internal box the union of
     * its children's, no cycle, and the free list.
     *
     * @param owner names the caller in messages
     * @return the number of leaves
     * @throws IllegalStateException describing the first violation found
     */
    int validate(String owner) {
        int reachable = 0;
        int leaves = 0;
        if (root != NULL) {
            check(root >= 0 && root < nodeHighWater, owner, "root %d out of range", root, 0);
            check(nodeParent[root] == NULL, owner, "root %d has parent %d", root, nodeParent[root]);
            int base = stackTop;
            try {
                push(root);
                while (stackTop > base) {
                    int node = stack[--stackTop];
                    reachable++;
                    check(reachable <= nodeHighWater, owner, "cycle through node %d", node, 0);
                    int height = nodeHeight[node];
                    int c1 = nodeChild1[node];
                    int c2 = nodeChild2[node];
                    check(height >= 0, owner, "free node %d is in the tree", node, 0);
                    if (height == 0) {
                        leaves++;
                        check(c1 == NULL && c2 == NULL, owner, "leaf %d has child %d", node, c1 != NULL ? c1 : c2);
                        continue;
                    }
                    check(nodeItem[node] == NULL, owner, "internal node %d has item %d", node, nodeItem[node]);
                    check(c1 >= 0 && c1 < nodeHighWater, owner, "node %d has bad child1 %d", node, c1);
                    check(c2 >= 0 && c2 < nodeHighWater, owner, "node %d has bad child2 %d", node, c2);
                    check(c1 != c2, owner, "node %d has child %d twice", node, c1);
                    check(nodeParent[c1] == node, owner, "child %d of node %d has another parent", c1, node);
                    check(nodeParent[c2] == node, owner, "child %d of node %d has another parent", c2, node);
                    check(nodeHeight[c1] >= 0 && nodeHeight[c2] >= 0, owner, "node %d has a free child (%d)", node,
                        nodeHeight[c1] < 0 ? c1 : c2);
                    check(height == 1 + Math.max(nodeHeight[c1], nodeHeight[c2]), owner, "node %d has wrong height %d",
                        node, height);
                    check(nodeMinX[node] == min(nodeMinX[c1], nodeMinX[c2])
                        && nodeMinY[node] == min(nodeMinY[c1], nodeMinY[c2])
                        && nodeMaxX[node] == max(nodeMaxX[c1], nodeMaxX[c2])
                        && nodeMaxY[node] == max(nodeMaxY[c1], nodeMaxY[c2]), owner,
                        "box of node %d is not the union of its children's (height %d)", node, height);
                    push(c1);
                    push(c2);
                }
            } finally {
                stackTop = base;
            }
        }
        check(reachable == nodeCount, owner, "%d nodes in the tree but %d allocated", reachable, nodeCount);
        int free = 0;
        for (int node = freeNodeHead; node != NULL; node = nodeParent[node]) {
            check(node >= 0 && node < nodeHighWater, owner, "free node %d out of range", node, 0);
            check(nodeHeight[node] == -1, owner, "node %d on the free list has height %d", node, nodeHeight[node]);
            free++;
            check(free <= nodeHighWater - nodeCount, owner, "node free list too long at %d", node, free);
        }
        check(free + nodeCount == nodeHighWater, owner, "%d free nodes, expected %d", free, nodeHighWater - nodeCount);
        return leaves;
    }

    static void check(boolean ok, String owner, String format, int a, int b) {
        if (!ok) {
            throw new IllegalStateException(owner + ".validate: " + String.format(format, a, b));
        }
    }
}
