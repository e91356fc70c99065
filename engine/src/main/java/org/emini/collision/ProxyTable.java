package org.emini.collision;

import java.util.Arrays;
import org.emini.internal.IdPool;

/**
 * The broadphase's proxies by id: each live proxy's leaf, tree and user data. Ids come from an
 * {@link IdPool}: dense in {@code [0, highWater)}, apart from node ids, and freed ids are reused
 * last-freed first, so the same calls give the same ids.
 */
final class ProxyTable {
    static final int NULL = -1;

    /** Leaf node of a live proxy in its tree, NULL for a free id. */
    int[] node;
    int[] userData;
    /** The tree a live proxy is in (the broadphase's tree index). */
    byte[] tree;
    private final IdPool ids;

    ProxyTable(int capacity) {
        node = new int[capacity];
        userData = new int[capacity];
        tree = new byte[capacity];
        ids = new IdPool(capacity);
    }

    /** @return a new id: the most recently freed, or else the smallest never used */
    int allocate() {
        int id = ids.allocate();
        if (id == node.length) {
            int capacity = 2 * id;
            node = Arrays.copyOf(node, capacity);
            userData = Arrays.copyOf(userData, capacity);
            tree = Arrays.copyOf(tree, capacity);
        }
        return id;
    }

    void free(int id) {
        node[id] = NULL;
        ids.free(id);
    }

    boolean isLive(int id) {
        return ids.isLive(id);
    }

    /** One more than the largest id ever used. */
    int highWater() {
        return ids.high();
    }

    /** The live proxies. */
    int count() {
        return ids.count();
    }

    /** Checks that the free list holds exactly the free ids. */
    void validateFreeList() {
        ids.validate("BroadPhase");
    }
}
