package org.emini.collision;

import java.util.Arrays;

/**
 * A dynamic AABB tree: leaves hold boxes and an int item each, internal nodes the union of their
 * children's boxes. Leaves are inserted by the surface-area heuristic (in 2D, the perimeter) and the
 * tree is kept balanced by AVL-like rotations on the way back up from every insertion and removal,
 * so its height stays O(log n) even for sorted insertion orders (Box2D's tree, on flat arrays).
 *
 * <p>Nodes live in primitive arrays indexed by node id, a node's box in one span of four floats and
 * its children, height and item in one of four ints; freed nodes are reused, arrays double when full,
 * queries walk an explicit stack kept as a field, so nothing is allocated once the tree has grown to
 * the scene. The shape of the tree, and so the order in which a query reports leaves,
 * depends only on the sequence of insertions and removals: the same calls give the same results.
 * A query's callback may query again (each query uses the stack above its caller's entries).
 */
final class DynamicTree {
    static final int NULL = -1;
    private static final int INITIAL_CAPACITY = 16;

    // A node's box, four floats (BOX apart), and its links and leaf data, four ints (LINK apart), so
    // that a query reads two neighbouring spans per node instead of eight arrays.
    private static final int BOX = 4;
    private static final int MIN_X = 0;
    private static final int MIN_Y = 1;
    private static final int MAX_X = 2;
    private static final int MAX_Y = 3;
    private static final int LINK = 4;
    private static final int CHILD1 = 0;
    private static final int CHILD2 = 1;
    /** Leaves have height 0, free nodes -1. */
    private static final int HEIGHT = 2;
    /** The item of a leaf, NULL for internal and free nodes. */
    private static final int ITEM = 3;

    private float[] box = new float[BOX * INITIAL_CAPACITY];
    private int[] link = new int[LINK * INITIAL_CAPACITY];
    /** Parent of a live node; next free node of a free one. */
    private int[] nodeParent = new int[INITIAL_CAPACITY];
    private int nodeHighWater;
    private int nodeCount;
    private int freeNodeHead = NULL;
    private int root = NULL;

    private int[] stack = new int[INITIAL_CAPACITY];
    private int stackTop;

    /** Adds a leaf with this box and item; returns its node id. */
    int insert(float minX, float minY, float maxX, float maxY, int item) {
        int leaf = allocateNode();
        setBox(leaf, minX, minY, maxX, maxY);
        link[LINK * leaf + ITEM] = item;
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
        setBox(leaf, minX, minY, maxX, maxY);
        insertLeaf(leaf);
    }

    private void setBox(int node, float minX, float minY, float maxX, float maxY) {
        int b = BOX * node;
        box[b + MIN_X] = minX;
        box[b + MIN_Y] = minY;
        box[b + MAX_X] = maxX;
        box[b + MAX_Y] = maxY;
    }

    /** Grows a leaf's box by {@code by} on every side (shrinks when negative) without refitting; call {@link #refitAll}. */
    void inflate(int leaf, float by) {
        box[BOX * leaf + MIN_X] -= by;
        box[BOX * leaf + MIN_Y] -= by;
        box[BOX * leaf + MAX_X] += by;
        box[BOX * leaf + MAX_Y] += by;
    }

    /** Recomputes every internal box from the leaves up, one height at a time (the shape is kept). */
    void refitAll() {
        int top = 0;
        for (int node = 0; node < nodeHighWater; node++) {
            top = Math.max(top, height(node));
        }
        for (int height = 1; height <= top; height++) {
            for (int node = 0; node < nodeHighWater; node++) {
                if (height(node) == height) {
                    refit(node);
                }
            }
        }
    }

    /** Translates every box by (−dx, −dy); rounding is monotonic, so internal boxes stay the unions. */
    void shift(float dx, float dy) {
        for (int i = 0; i < nodeHighWater; i++) {
            if (height(i) >= 0) {
                box[BOX * i + MIN_X] -= dx;
                box[BOX * i + MIN_Y] -= dy;
                box[BOX * i + MAX_X] -= dx;
                box[BOX * i + MAX_Y] -= dy;
            }
        }
    }

    private int height(int node) {
        return link[LINK * node + HEIGHT];
    }

    private int child1(int node) {
        return link[LINK * node + CHILD1];
    }

    private int child2(int node) {
        return link[LINK * node + CHILD2];
    }

    private int item(int node) {
        return link[LINK * node + ITEM];
    }

    float minX(int node) {
        return box[BOX * node + MIN_X];
    }

    float minY(int node) {
        return box[BOX * node + MIN_Y];
    }

    float maxX(int node) {
        return box[BOX * node + MAX_X];
    }

    float maxY(int node) {
        return box[BOX * node + MAX_Y];
    }

    /** Whether a node id is a live leaf holding this item. */
    boolean holds(int node, int item) {
        return node >= 0 && node < nodeHighWater && height(node) == 0 && item(node) == item;
    }

    /** 0 for an empty tree or a single leaf, otherwise the edges on the longest root-to-leaf path. */
    int height() {
        return root == NULL ? 0 : height(root);
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
                int b = BOX * node;
                if (box[b + MIN_X] > maxX || minX > box[b + MAX_X] || box[b + MIN_Y] > maxY || minY > box[b + MAX_Y]) {
                    continue;
                }
                int l = LINK * node;
                if (link[l + HEIGHT] > 0) {
                    push(link[l + CHILD1]);
                    push(link[l + CHILD2]);
                } else if (!callback.reportProxy(link[l + ITEM])) {
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
                int b = BOX * node;
                if (!sweep.meets(box[b + MIN_X], box[b + MIN_Y], box[b + MAX_X], box[b + MAX_Y])) {
                    continue;
                }
                int l = LINK * node;
                if (link[l + HEIGHT] > 0) {
                    push(link[l + CHILD1]);
                    push(link[l + CHILD2]);
                } else if (!callback.reportProxy(link[l + ITEM])) {
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
            if (nodeHighWater == nodeParent.length) {
                growNodes();
            }
            node = nodeHighWater++;
        }
        nodeParent[node] = NULL;
        link[LINK * node + CHILD1] = NULL;
        link[LINK * node + CHILD2] = NULL;
        link[LINK * node + HEIGHT] = 0;
        link[LINK * node + ITEM] = NULL;
        nodeCount++;
        return node;
    }

    private void releaseNode(int node) {
        nodeParent[node] = freeNodeHead;
        link[LINK * node + CHILD1] = NULL;
        link[LINK * node + CHILD2] = NULL;
        link[LINK * node + HEIGHT] = -1;
        link[LINK * node + ITEM] = NULL;
        freeNodeHead = node;
        nodeCount--;
    }

    private void growNodes() {
        int capacity = nodeParent.length * 2;
        box = Arrays.copyOf(box, BOX * capacity);
        link = Arrays.copyOf(link, LINK * capacity);
        nodeParent = Arrays.copyOf(nodeParent, capacity);
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
        float minX = minX(leaf);
        float minY = minY(leaf);
        float maxX = maxX(leaf);
        float maxY = maxY(leaf);

        int index = root;
        while (height(index) > 0) {
            int child1 = child1(index);
            int child2 = child2(index);
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
        link[LINK * newParent + CHILD1] = sibling;
        link[LINK * newParent + CHILD2] = leaf;
        nodeParent[sibling] = newParent;
        nodeParent[leaf] = newParent;
        if (oldParent == NULL) {
            root = newParent;
        } else if (child1(oldParent) == sibling) {
            link[LINK * oldParent + CHILD1] = newParent;
        } else {
            link[LINK * oldParent + CHILD2] = newParent;
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
        int sibling = child1(parent) == leaf ? child2(parent) : child1(parent);
        nodeParent[leaf] = NULL;
        releaseNode(parent);
        nodeParent[sibling] = grandParent;
        if (grandParent == NULL) {
            root = sibling;
            return;
        }
        if (child1(grandParent) == parent) {
            link[LINK * grandParent + CHILD1] = sibling;
        } else {
            link[LINK * grandParent + CHILD2] = sibling;
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
        int c1 = child1(node);
        int c2 = child2(node);
        setBox(node, min(minX(c1), minX(c2)), min(minY(c1), minY(c2)), max(maxX(c1), maxX(c2)), max(maxY(c1), maxY(c2)));
        link[LINK * node + HEIGHT] = 1 + Math.max(height(c1), height(c2));
    }

    /**
     * If the children's heights of {@code a} differ by more than one, rotates the taller child up
     * into a's place and returns it; otherwise returns a. The children of a must be up to date.
     */
    private int balance(int a) {
        // a's own height may be stale (a new parent), so only its children's heights are used.
        int b = child1(a);
        int c = child2(a);
        int diff = height(c) - height(b);
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
        int f = child1(p);
        int g = child2(p);
        int keep;
        int give;
        if (height(f) > height(g)) {
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
        } else if (child1(up) == a) {
            link[LINK * up + CHILD1] = p;
        } else {
            link[LINK * up + CHILD2] = p;
        }
        link[LINK * p + CHILD1] = a;
        link[LINK * p + CHILD2] = keep;
        nodeParent[keep] = p;
        nodeParent[a] = p;
        if (pIsChild2) {
            link[LINK * a + CHILD2] = give;
        } else {
            link[LINK * a + CHILD1] = give;
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
        return height(child) == 0 ? combined : combined - perimeter(child);
    }

    private float perimeter(int node) {
        return 2f * ((maxX(node) - minX(node)) + (maxY(node) - minY(node)));
    }

    private float unionPerimeter(int node, float minX, float minY, float maxX, float maxY) {
        float w = max(maxX(node), maxX) - min(minX(node), minX);
        float h = max(maxY(node), maxY) - min(minY(node), minY);
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
                    int height = height(node);
                    int c1 = child1(node);
                    int c2 = child2(node);
                    check(height >= 0, owner, "free node %d is in the tree", node, 0);
                    if (height == 0) {
                        leaves++;
                        check(c1 == NULL && c2 == NULL, owner, "leaf %d has child %d", node, c1 != NULL ? c1 : c2);
                        continue;
                    }
                    check(item(node) == NULL, owner, "internal node %d has item %d", node, item(node));
                    check(c1 >= 0 && c1 < nodeHighWater, owner, "node %d has bad child1 %d", node, c1);
                    check(c2 >= 0 && c2 < nodeHighWater, owner, "node %d has bad child2 %d", node, c2);
                    check(c1 != c2, owner, "node %d has child %d twice", node, c1);
                    check(nodeParent[c1] == node, owner, "child %d of node %d has another parent", c1, node);
                    check(nodeParent[c2] == node, owner, "child %d of node %d has another parent", c2, node);
                    check(height(c1) >= 0 && height(c2) >= 0, owner, "node %d has a free child (%d)", node,
                        height(c1) < 0 ? c1 : c2);
                    check(height == 1 + Math.max(height(c1), height(c2)), owner, "node %d has wrong height %d",
                        node, height);
                    check(minX(node) == min(minX(c1), minX(c2))
                        && minY(node) == min(minY(c1), minY(c2))
                        && maxX(node) == max(maxX(c1), maxX(c2))
                        && maxY(node) == max(maxY(c1), maxY(c2)), owner,
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
            check(height(node) == -1, owner, "node %d on the free list has height %d", node, height(node));
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
