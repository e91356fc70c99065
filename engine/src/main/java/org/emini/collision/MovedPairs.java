package org.emini.collision;

import java.util.Arrays;
import org.emini.internal.HeapSort;

/**
 * The broadphase's move buffer and the pairs it yields: the proxies moved since the last pair
 * update (each once), and the pairs collected for them from the trees, sorted, up to a limit. A
 * pair of two moved proxies is kept only while querying the smaller id, so each pair is found once.
 */
final class MovedPairs implements QueryCallback {
    static final int NULL = -1;

    /** Index in {@link #moves} by proxy id, NULL when the proxy has not moved. */
    private int[] moveIndex;
    private int[] moves = new int[16];
    private int moveCount;

    /** Pairs as (smaller id &lt;&lt; 32 | larger id), so that sorting the longs sorts the pairs. */
    private long[] pairs = new long[16];
    private int pairCount;
    private int limit = Integer.MAX_VALUE;
    private boolean limitReached;
    private int queryProxy;
    // The update's callback, asked of each pair whether it is known, and the proxies' user data.
    private PairCallback receiver;
    private int[] userData;

    MovedPairs(int proxyCapacity) {
        moveIndex = new int[proxyCapacity];
    }

    /** A new proxy id starts unmoved. */
    void reset(int proxyId) {
        if (proxyId >= moveIndex.length) {
            moveIndex = Arrays.copyOf(moveIndex, Math.max(proxyId + 1, 2 * moveIndex.length));
        }
        moveIndex[proxyId] = NULL;
    }

    void add(int proxyId) {
        if (moveIndex[proxyId] != NULL) {
            return;
        }
        if (moveCount == moves.length) {
            moves = Arrays.copyOf(moves, moveCount * 2);
        }
        moveIndex[proxyId] = moveCount;
        moves[moveCount++] = proxyId;
    }

    /** Removes a proxy by moving the last entry into its slot. */
    void remove(int proxyId) {
        int index = moveIndex[proxyId];
        if (index == NULL) {
            return;
        }
        int last = moves[--moveCount];
        moves[index] = last;
        moveIndex[last] = index;
        moveIndex[proxyId] = NULL;
    }

    boolean contains(int proxyId) {
        return moveIndex[proxyId] != NULL;
    }

    int moveCount() {
        return moveCount;
    }

    int moved(int i) {
        return moves[i];
    }

    void setLimit(int limit) {
        this.limit = limit;
    }

    int limit() {
        return limit;
    }

    boolean limitReached() {
        return limitReached;
    }

    /** Starts collecting pairs, leaving out those the receiver knows. */
    void beginPairs(PairCallback receiver, int[] userData) {
        pairCount = 0;
        limitReached = false;
        this.receiver = receiver;
        this.userData = userData;
    }

    /** Collects the pairs of one moved proxy with the proxies of a tree whose boxes meet the box. */
    void collect(int proxyId, DynamicTree tree, float minX, float minY, float maxX, float maxY) {
        queryProxy = proxyId;
        if (!tree.query(minX, minY, maxX, maxY, this)) {
            limitReached = true;
        }
    }

    /** Empties the move buffer and sorts the pairs; done before any callback runs. */
    void endPairs() {
        for (int i = 0; i < moveCount; i++) {
            moveIndex[moves[i]] = NULL;
        }
        moveCount = 0;
        receiver = null;
        userData = null;
        HeapSort.sort(pairs, pairCount);
    }

    int pairCount() {
        return pairCount;
    }

    /** @return the smaller proxy id of pair i in the high 32 bits, the larger in the low ones */
    long pair(int i) {
        return pairs[i];
    }

    @Override
    public boolean reportProxy(int other) {
        if (other == queryProxy || (other < queryProxy && moveIndex[other] != NULL)) {
            return true;
        }
        if (receiver.isKnownPair(userData[queryProxy], userData[other])) {
            return true;
        }
        if (pairCount == limit) {
            return false;
        }
        if (pairCount == pairs.length) {
            pairs = Arrays.copyOf(pairs, (int) Math.min(limit, 2L * pairCount));
        }
        pairs[pairCount++] = other < queryProxy ? ((long) other << 32) | queryProxy : ((long) queryProxy << 32) | other;
        return true;
    }

    /**
     * Checks the move buffer against the live proxies.
     *
     * @param live whether each proxy id below {@code highWater} is live
     */
    void validate(boolean[] live, int highWater) {
        int moved = 0;
        for (int p = 0; p < highWater; p++) {
            int index = moveIndex[p];
            if (index == NULL) {
                continue;
            }
            DynamicTree.check(live[p], "BroadPhase", "free proxy %d is in the move buffer", p, 0);
            moved++;
            DynamicTree.check(index >= 0 && index < moveCount && moves[index] == p, "BroadPhase",
                "proxy %d has bad move index %d", p, index);
        }
        DynamicTree.check(moved == moveCount, "BroadPhase", "%d moved proxies, move count says %d", moved, moveCount);
    }
}
