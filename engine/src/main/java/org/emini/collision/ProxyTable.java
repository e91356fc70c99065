package org.emini.collision;

import java.util.Arrays;

/**
 * The broadphase's proxies by id: each live proxy's leaf, tree and user data. Ids stay dense in
 * {@code [0, highWater)}, apart from node ids, and freed ids are reused last-freed first, so the
 * same calls give the same ids.
 */
final class ProxyTable {
    static final int NULL = -1;

    /** Leaf node of a live proxy in its tree, NULL for a free id. */
    int[] node;
    int[] userData;
    /** The tree a live proxy is in (the broadphase's tree index). */
    byte[] tree;
    /** Next free id of a free id. */
    private int[] nextFree;
    int highWater;
    int count;
    private int freeHead = NULL;

    ProxyTable(int capacity) {
        node = new int[capacity];
        userData = new int[capacity];
        tree = new byte[capacity];
        nextFree = new int[capacity];
    }

    /** @return a new id: the most recently freed, or else the smallest never used */
    int allocate() {
        int id;
        if (freeHead != NULL) {
            id = freeHead;
            freeHead = nextFree[id];
        } else {
            if (highWater == node.length) {
                int capacity = highWater * 2;
                node = Arrays.copyOf(node, capacity);
                userData = Arrays.copyOf(userData, capacity);
                tree = Arrays.copyOf(tree, capacity);
                nextFree = Arrays.copyOf(nextFree, capacity);
            }
            id = highWater++;
        }
        nextFree[id] = NULL;
        count++;
        return id;
    }

    void free(int id) {
        node[id] = NULL;
        nextFree[id] = freeHead;
        freeHead = id;
        count--;
    }

    boolean isLive(int id) {
        return id >= 0 && id < highWater && node[id] != NULL;
    }

    /** Checks that the free list holds exactly the free ids. */
    void validateFreeList() {
        int free = 0;
        for (int p = freeHead; p != NULL; p = nextFree[p]) {
            DynamicTree.check(p >= 0 && p < highWater && node[p] == NULL, "BroadPhase",
                "proxy free list holds live or bad id %d", p, 0);
            free++;
            DynamicTree.check(free <= highWater - count, "BroadPhase", "proxy free list too long at %d", p, free);
        }
        DynamicTree.check(free + count == highWater, "BroadPhase", "%d free proxy ids, expected %d", free,
            highWater - count);
    }
}
