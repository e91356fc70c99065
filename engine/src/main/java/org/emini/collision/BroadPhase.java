package org.emini.collision;

import org.emini.math.EMath;

/**
 * The broadphase: dynamic AABB trees of proxies with fat AABBs, a move buffer and pair
 * generation for moved proxies only.
 *
 * <p>Proxies are <em>static</em> or <em>dynamic</em>, and each kind has its own tree (as in Box2D
 * v3): pairs of two static proxies are never reported, so a moved static proxy is looked up in the
 * dynamic tree only, and a query may search one kind alone ({@link #queryStatic},
 * {@link #queryDynamic}). Proxies are dynamic unless created or marked static.
 *
 * <p>Each proxy stands for one collision shape. The tree stores a <em>fat</em> AABB per proxy: the
 * tight AABB enlarged by {@code margin} on every side and, when the proxy is moved, stretched
 * along the expected displacement. As long as a shape's tight AABB stays inside its fat AABB,
 * {@link #moveProxy} does nothing, so resting and slowly moving bodies never touch the tree.
 *
 * <p>Each tree is a DynamicTree (this package): leaves inserted by the surface-area heuristic and kept
 * balanced by rotations, so its height stays O(log n) even for sorted insertion orders. This class
 * adds what makes them a broadphase: proxies ({@code ProxyTable}) and their fat boxes, and the
 * moved proxies with their pairs ({@code MovedPairs}).
 *
 * <p>Proxy ids are small non-negative ints, dense in {@code [0, peak proxy count)}; freed ids are
 * reused last-freed first. Everything is deterministic: the same sequence of calls gives the same
 * ids, the same tree and the same pairs in the same order.
 *
 * <p>Storage is a set of growable primitive arrays that double when full, so once they have grown
 * to the size of the scene nothing is allocated. The class is not thread-safe, and it must not be
 * modified from inside its callbacks (doing so throws {@link IllegalStateException}).
 */
public final class BroadPhase {
    /**
     * How many steps of displacement a moved fat AABB is stretched by (Box2D v2 uses 4): a body
     * moving steadily in a straight line is re-inserted only about every fourth step.
     */
    public static final float DISPLACEMENT_MULTIPLIER = 4f;

    /**
     * A fat AABB that still contains its shape is re-inserted anyway when it exceeds the new fat
     * AABB by more than this many margins plus the stretch on some side (a fast body that has
     * since slowed down).
     */
    private static final float SHRINK_MARGINS = 4f;

    private static final int NULL = -1;
    private static final int STATIC_TREE = 0;
    private static final int DYNAMIC_TREE = 1;
    private static final int INITIAL_CAPACITY = 16;

    private float margin;

    /** The two trees, indexed by {@link #STATIC_TREE} and {@link #DYNAMIC_TREE}; leaves hold proxy ids. */
    private final DynamicTree[] trees = {new DynamicTree(), new DynamicTree()};

    private final ProxyTable proxies = new ProxyTable(INITIAL_CAPACITY);

    /** The proxies moved since the last updatePairs, and their pairs. */
    private final MovedPairs moved = new MovedPairs(INITIAL_CAPACITY);

    /** Number of callbacks currently running; the broadphase is read-only while it is positive. */
    private int lockDepth;

    /**
     * Creates an empty broadphase.
     *
     * @param margin the distance (px) by which fat AABBs exceed the tight ones on every side;
     *     finite and non-negative
     * @throws IllegalArgumentException if margin is negative, NaN or infinite
     */
    public BroadPhase(float margin) {
        if (!EMath.isFinite(margin) || margin < 0f) {
            throw new IllegalArgumentException(
                    "BroadPhase: margin (" + margin + ") must be finite and >= 0");
        }
        this.margin = margin;
    }

    /**
     * The margin by which fat AABBs exceed the tight ones.
     *
     * @return the distance (px)
     */
    public float getMargin() {
        return margin;
    }

    /**
     * Changes the margin of every fat AABB at once: each grows (or shrinks) by the difference on
     * every side, keeping its stretch, and every proxy goes into the move buffer, so the next
     * {@link #updatePairs} reports the pairs a larger margin brings (a pair must be reported when
     * fat boxes begin to overlap). Costs like moving every proxy; nothing when the margin is the
     * same.
     *
     * @param margin the distance (px), finite and non-negative
     * @throws IllegalArgumentException if margin is negative, NaN or infinite
     * @throws IllegalStateException if called from inside a callback
     */
    public void setMargin(float margin) {
        checkUnlocked("setMargin");
        if (!EMath.isFinite(margin) || margin < 0f) {
            throw new IllegalArgumentException("setMargin: margin (" + margin + ") must be finite and >= 0");
        }
        float grow = margin - this.margin;
        if (grow == 0f) {
            return;
        }
        this.margin = margin;
        for (int proxyId = 0; proxyId < proxies.highWater(); proxyId++) {
            int leaf = proxies.node[proxyId];
            if (leaf != NULL) {
                trees[proxies.tree[proxyId]].inflate(leaf, grow);
                moved.add(proxyId);
            }
        }
        trees[STATIC_TREE].refitAll();
        trees[DYNAMIC_TREE].refitAll();
    }

    /**
     * Bounds the pairs one {@link #updatePairs} collects (known pairs are not collected), so that many
     * proxies in one spot (n of them overlap in n(n − 1)/2 pairs) cost bounded time and memory.
     * Default: no limit.
     *
     * @param limit the most pairs collected, &gt; 0
     * @throws IllegalArgumentException if limit is not positive
     */
    public void setPairLimit(int limit) {
        if (limit <= 0) {
            throw new IllegalArgumentException("setPairLimit: limit (" + limit + ") must be > 0");
        }
        moved.setLimit(limit);
    }

    /**
     * The most pairs one {@link #updatePairs} collects.
     *
     * @return the limit
     */
    public int getPairLimit() {
        return moved.limit();
    }

    /**
     * Whether the last {@link #updatePairs} stopped at the limit: it reported the limit's worth of
     * pairs, in order, and dropped the rest (they are reported again when their proxies next move).
     *
     * @return true when pairs were dropped
     */
    public boolean isPairLimitReached() {
        return moved.limitReached();
    }

    // ------------------------------------------------------------------------------------------
    // Proxies

    /**
     * Creates a proxy and puts it in the move buffer, so that its pairs are reported by the next
     * {@link #updatePairs}. Its fat AABB is the tight one enlarged by the margin.
     *
     * @param minX the left of the tight AABB
     * @param minY the top of the tight AABB
     * @param maxX the right of the tight AABB, at least minX
     * @param maxY the bottom of the tight AABB, at least minY
     * @param userData a value handed back with the proxy's pairs, typically a shape index
     * @return the new proxy id: the most recently freed id, or else the smallest never used
     * @throws IllegalArgumentException if a coordinate is NaN or infinite, or min &gt; max
     * @throws IllegalStateException if called from inside a callback
     */
    public int createProxy(float minX, float minY, float maxX, float maxY, int userData) {
        return createProxy(minX, minY, maxX, maxY, userData, false);
    }

    /**
     * Creates a static or dynamic proxy (see {@link #createProxy(float, float, float, float, int)}).
     * Two static proxies never make a pair.
     *
     * @param minX the left of the tight AABB
     * @param minY the top of the tight AABB
     * @param maxX the right of the tight AABB, at least minX
     * @param maxY the bottom of the tight AABB, at least minY
     * @param userData a value handed back with the proxy's pairs, typically a shape index
     * @param isStatic true for a static proxy
     * @return the new proxy id: the most recently freed id, or else the smallest never used
     * @throws IllegalArgumentException if a coordinate is NaN or infinite, or min &gt; max
     * @throws IllegalStateException if called from inside a callback
     */
    public int createProxy(
            float minX, float minY, float maxX, float maxY, int userData, boolean isStatic) {
        checkUnlocked("createProxy");
        BoxChecks.box("createProxy", minX, minY, maxX, maxY);
        int proxyId = proxies.allocate();
        int tree = isStatic ? STATIC_TREE : DYNAMIC_TREE;
        proxies.node[proxyId] = trees[tree].insert(minX - margin, minY - margin, maxX + margin, maxY + margin, proxyId);
        proxies.userData[proxyId] = userData;
        moved.reset(proxyId);
        proxies.tree[proxyId] = (byte) tree;
        moved.add(proxyId);
        return proxyId;
    }

    /**
     * Destroys a proxy; its id may be returned by a later {@link #createProxy}. It leaves the move
     * buffer, so the next {@link #updatePairs} reports no pair with it.
     *
     * @param proxyId a live proxy id
     * @throws IllegalArgumentException if the id is unknown or already destroyed
     * @throws IllegalStateException if called from inside a callback
     */
    public void destroyProxy(int proxyId) {
        checkUnlocked("destroyProxy");
        checkProxy("destroyProxy", proxyId);
        moved.remove(proxyId);
        trees[proxies.tree[proxyId]].remove(proxies.node[proxyId]);
        proxies.free(proxyId);
    }

    /**
     * Updates a proxy after its shape moved.
     *
     * <p>If the tight AABB, swept by the displacement, is still inside the fat one, nothing happens
     * and false is returned;
     * this is the common case for resting and slowly moving shapes. Otherwise the proxy gets the
     * fat AABB {@code tight + margin}, stretched on the side the shape moves towards by
     * {@link #DISPLACEMENT_MULTIPLIER} times the displacement, is re-inserted in the tree and put
     * in the move buffer, and true is returned.
     *
     * <p>One more case re-inserts, as in Box2D v2.4: the tight AABB is inside the fat one, but the
     * fat one exceeds the fat AABB just described, on some side, by more than four margins plus
     * the stretch along that axis. This happens after a fast shape slowed down; such stale
     * oversized boxes would otherwise report needless pairs for ever.
     *
     * @param proxyId a live proxy id
     * @param minX the left of the new tight AABB
     * @param minY the top of the new tight AABB
     * @param maxX the right of the new tight AABB, at least minX
     * @param maxY the bottom of the new tight AABB, at least minY
     * @param dx the expected x displacement of the shape during the next step (px)
     * @param dy the expected y displacement of the shape during the next step (px)
     * @return true if the proxy was re-inserted (and its pairs will be reported), false if not
     * @throws IllegalArgumentException if the id is unknown or destroyed, a value is NaN or
     *     infinite, or min &gt; max
     * @throws IllegalStateException if called from inside a callback
     */
    public boolean moveProxy(
            int proxyId, float minX, float minY, float maxX, float maxY, float dx, float dy) {
        checkUnlocked("moveProxy");
        checkProxy("moveProxy", proxyId);
        BoxChecks.box("moveProxy", minX, minY, maxX, maxY);
        BoxChecks.finite("moveProxy", "dx", dx);
        BoxChecks.finite("moveProxy", "dy", dy);
        if (keepsBox(proxyId, minX, minY, maxX, maxY, dx, dy)) {
            return false;
        }
        float ex = DISPLACEMENT_MULTIPLIER * dx;
        float ey = DISPLACEMENT_MULTIPLIER * dy;
        trees[proxies.tree[proxyId]].move(proxies.node[proxyId], fatLow(minX, ex), fatLow(minY, ey), fatHigh(maxX, ex),
            fatHigh(maxY, ey));
        moved.add(proxyId);
        return true;
    }

    /**
     * Whether {@link #moveProxy} with these arguments would leave the proxy where it is (and return
     * false). It only reads, so threads may ask it about different proxies at once while nothing
     * changes the broadphase; it checks nothing: the arguments must be valid for moveProxy.
     *
     * @param proxyId a live proxy id
     * @param minX the left of the new tight AABB
     * @param minY the top of the new tight AABB
     * @param maxX the right of the new tight AABB, at least minX
     * @param maxY the bottom of the new tight AABB, at least minY
     * @param dx the expected x displacement of the shape during the next step (px)
     * @param dy the expected y displacement of the shape during the next step (px)
     * @return true if the proxy's fat AABB holds the swept tight one and is not oversized
     */
    public boolean keepsBox(int proxyId, float minX, float minY, float maxX, float maxY, float dx, float dy) {
        int leaf = proxies.node[proxyId];
        DynamicTree tree = trees[proxies.tree[proxyId]];
        float oldMinX = tree.minX(leaf);
        float oldMinY = tree.minY(leaf);
        float oldMaxX = tree.maxX(leaf);
        float oldMaxY = tree.maxY(leaf);
        // The old box must hold the tight box swept by the coming displacement, or a body that was
        // set moving fast inside its box would cross others unseen (no pair, no speculative contact).
        float sweptMinX = dx < 0f ? minX + dx : minX;
        float sweptMinY = dy < 0f ? minY + dy : minY;
        float sweptMaxX = dx > 0f ? maxX + dx : maxX;
        float sweptMaxY = dy > 0f ? maxY + dy : maxY;
        if (!(oldMinX <= sweptMinX && oldMinY <= sweptMinY && sweptMaxX <= oldMaxX && sweptMaxY <= oldMaxY)) {
            return false;
        }
        // The old box must not be oversized either. The stretch is added to the slack so that a
        // steadily moving shape, whose old box trails behind, is re-inserted only when it leaves its box.
        float ex = DISPLACEMENT_MULTIPLIER * dx;
        float ey = DISPLACEMENT_MULTIPLIER * dy;
        float slackX = SHRINK_MARGINS * margin + Math.abs(ex);
        float slackY = SHRINK_MARGINS * margin + Math.abs(ey);
        return fatLow(minX, ex) - slackX <= oldMinX && fatLow(minY, ey) - slackY <= oldMinY
            && oldMaxX <= fatHigh(maxX, ex) + slackX && oldMaxY <= fatHigh(maxY, ey) + slackY;
    }

    /** A fat box's low side: the margin, and the stretch when it points that way. */
    private float fatLow(float min, float stretch) {
        float low = min - margin;
        if (stretch < 0f) {
            low += stretch;
        }
        return low;
    }

    /** A fat box's high side: the margin, and the stretch when it points that way. */
    private float fatHigh(float max, float stretch) {
        float high = max + margin;
        if (stretch >= 0f) {
            high += stretch;
        }
        return high;
    }

    /**
     * Makes a proxy static or dynamic, moving it to the other tree (its fat AABB is kept) and
     * into the move buffer when that changes it; does nothing when it already is of that kind.
     *
     * @param proxyId a live proxy id
     * @param isStatic true to make it static
     * @throws IllegalArgumentException if the id is unknown or destroyed
     * @throws IllegalStateException if called from inside a callback
     */
    public void setStatic(int proxyId, boolean isStatic) {
        checkUnlocked("setStatic");
        checkProxy("setStatic", proxyId);
        int tree = isStatic ? STATIC_TREE : DYNAMIC_TREE;
        if (proxies.tree[proxyId] == tree) {
            return;
        }
        DynamicTree from = trees[proxies.tree[proxyId]];
        int leaf = proxies.node[proxyId];
        float minX = from.minX(leaf);
        float minY = from.minY(leaf);
        float maxX = from.maxX(leaf);
        float maxY = from.maxY(leaf);
        from.remove(leaf);
        proxies.node[proxyId] = trees[tree].insert(minX, minY, maxX, maxY, proxyId);
        proxies.tree[proxyId] = (byte) tree;
        moved.add(proxyId);
    }

    /**
     * Whether a proxy is static.
     *
     * @param proxyId a live proxy id
     * @return true if it was created or marked static
     * @throws IllegalArgumentException if the id is unknown or destroyed
     */
    public boolean isStatic(int proxyId) {
        checkProxy("isStatic", proxyId);
        return proxies.tree[proxyId] == STATIC_TREE;
    }

    /**
     * Puts a proxy in the move buffer without changing its AABB, so that the next
     * {@link #updatePairs} reports its pairs again (for example after a filter change).
     *
     * @param proxyId a live proxy id
     * @throws IllegalArgumentException if the id is unknown or destroyed
     * @throws IllegalStateException if called from inside a callback
     */
    public void touchProxy(int proxyId) {
        checkUnlocked("touchProxy");
        checkProxy("touchProxy", proxyId);
        moved.add(proxyId);
    }

    /**
     * Whether the fat AABBs of two proxies overlap; boxes that only touch overlap.
     *
     * @param proxyA a live proxy id
     * @param proxyB a live proxy id
     * @return true if the fat AABBs overlap
     * @throws IllegalArgumentException if an id is unknown or destroyed
     */
    public boolean testOverlap(int proxyA, int proxyB) {
        checkProxy("testOverlap", proxyA);
        checkProxy("testOverlap", proxyB);
        DynamicTree ta = trees[proxies.tree[proxyA]];
        DynamicTree tb = trees[proxies.tree[proxyB]];
        int a = proxies.node[proxyA];
        int b = proxies.node[proxyB];
        return ta.minX(a) <= tb.maxX(b) && tb.minX(b) <= ta.maxX(a)
                && ta.minY(a) <= tb.maxY(b) && tb.minY(b) <= ta.maxY(a);
    }

    // ------------------------------------------------------------------------------------------
    // Pairs and queries

    /**
     * Reports the pairs of the proxies moved since the last call, then empties the move buffer.
     *
     * <p>For every proxy in the move buffer (created, moved by {@link #moveProxy} returning true,
     * or touched, and not destroyed since), the tree is queried with its fat AABB. Every pair of
     * distinct proxies whose fat AABBs overlap, of which at least one is in the move buffer and at
     * least one is dynamic, is reported exactly once, in increasing order of (smaller id, larger id), with the user data of
     * the smaller id first, unless the callback {@linkplain PairCallback#isKnownPair knows it}. No
     * other pair is reported. Beyond the {@linkplain #setPairLimit pair limit}, collection stops (in
     * move-buffer order) and the remaining pairs are dropped.
     *
     * @param callback receives the pairs; it must not modify this broadphase
     * @throws IllegalArgumentException if callback is null
     * @throws IllegalStateException if called from inside a callback
     */
    public void updatePairs(PairCallback callback) {
        checkUnlocked("updatePairs");
        if (callback == null) {
            throw new IllegalArgumentException("updatePairs: callback is null");
        }
        moved.beginPairs(callback, proxies.userData);
        for (int i = 0, n = moved.moveCount(); i < n && !moved.limitReached(); i++) {
            int proxy = moved.moved(i);
            // Moved proxies meet the dynamic ones, and the static ones too when dynamic themselves.
            collectPairs(proxy, DYNAMIC_TREE);
            if (proxies.tree[proxy] == DYNAMIC_TREE && !moved.limitReached()) {
                collectPairs(proxy, STATIC_TREE);
            }
        }
        // Emptied before the callbacks run, so that a throwing callback leaves a clean state.
        moved.endPairs();

        lockDepth++;
        try {
            for (int i = 0, n = moved.pairCount(); i < n; i++) {
                long key = moved.pair(i);
                callback.addPair(proxies.userData[(int) (key >>> 32)], proxies.userData[(int) key]);
            }
        } finally {
            lockDepth--;
        }
    }

    private void collectPairs(int queryProxy, int tree) {
        DynamicTree own = trees[proxies.tree[queryProxy]];
        int leaf = proxies.node[queryProxy];
        moved.collect(queryProxy, trees[tree], own.minX(leaf), own.minY(leaf), own.maxX(leaf), own.maxY(leaf));
    }

    /**
     * Reports every proxy whose fat AABB overlaps a box (touching counts), in tree order (the
     * static tree first), until the callback returns false.
     *
     * @param minX the left of the box
     * @param minY the top of the box
     * @param maxX the right of the box, at least minX
     * @param maxY the bottom of the box, at least minY
     * @param callback receives the proxy ids; it must not modify this broadphase but may query it
     * @throws IllegalArgumentException if a coordinate is NaN or infinite, min &gt; max, or callback
     *     is null
     */
    public void query(float minX, float minY, float maxX, float maxY, QueryCallback callback) {
        BoxChecks.query("query", minX, minY, maxX, maxY, callback);
        if (queryTree(STATIC_TREE, minX, minY, maxX, maxY, callback)) {
            queryTree(DYNAMIC_TREE, minX, minY, maxX, maxY, callback);
        }
    }

    /**
     * Like {@link #query}, but reports the static proxies only.
     *
     * @param minX the left of the box
     * @param minY the top of the box
     * @param maxX the right of the box, at least minX
     * @param maxY the bottom of the box, at least minY
     * @param callback receives the proxy ids; it must not modify this broadphase but may query it
     * @throws IllegalArgumentException if a coordinate is NaN or infinite, min &gt; max, or callback
     *     is null
     */
    public void queryStatic(float minX, float minY, float maxX, float maxY, QueryCallback callback) {
        BoxChecks.query("queryStatic", minX, minY, maxX, maxY, callback);
        queryTree(STATIC_TREE, minX, minY, maxX, maxY, callback);
    }

    /**
     * Like {@link #query}, but reports the dynamic proxies only.
     *
     * @param minX the left of the box
     * @param minY the top of the box
     * @param maxX the right of the box, at least minX
     * @param maxY the bottom of the box, at least minY
     * @param callback receives the proxy ids; it must not modify this broadphase but may query it
     * @throws IllegalArgumentException if a coordinate is NaN or infinite, min &gt; max, or callback
     *     is null
     */
    public void queryDynamic(
            float minX, float minY, float maxX, float maxY, QueryCallback callback) {
        BoxChecks.query("queryDynamic", minX, minY, maxX, maxY, callback);
        queryTree(DYNAMIC_TREE, minX, minY, maxX, maxY, callback);
    }

    /**
     * Like {@link #query}, for a box swept along a translation (a ray: a point swept): reports the
     * proxies whose fat AABB the sweep meets, walking only the parts of the trees it passes
     * through, so a long diagonal ray costs in proportion to what lies along it.
     *
     * @param sweep the swept box
     * @param callback receives the proxy ids; it must not modify this broadphase but may query it
     * @throws IllegalArgumentException if sweep or callback is null
     */
    public void querySwept(SweptBox sweep, QueryCallback callback) {
        if (sweep == null || callback == null) {
            throw new IllegalArgumentException("querySwept: " + (sweep == null ? "sweep" : "callback") + " is null");
        }
        lockDepth++;
        try {
            if (trees[STATIC_TREE].querySwept(sweep, callback)) {
                trees[DYNAMIC_TREE].querySwept(sweep, callback);
            }
        } finally {
            lockDepth--;
        }
    }

    /** Queries one tree; returns false if the callback stopped the query. */
    private boolean queryTree(
            int tree, float minX, float minY, float maxX, float maxY, QueryCallback callback) {
        lockDepth++;
        try {
            return trees[tree].query(minX, minY, maxX, maxY, callback);
        } finally {
            lockDepth--;
        }
    }

    // ------------------------------------------------------------------------------------------
    // Accessors

    /**
     * The user data given when the proxy was created.
     *
     * @param proxyId a live proxy id
     * @return its user data
     * @throws IllegalArgumentException if the id is unknown or destroyed
     */
    public int getUserData(int proxyId) {
        checkProxy("getUserData", proxyId);
        return proxies.userData[proxyId];
    }

    /**
     * The left of a proxy's fat AABB.
     *
     * @param proxyId a live proxy id
     * @return the fat AABB's minimum x
     * @throws IllegalArgumentException if the id is unknown or destroyed
     */
    public float getFatMinX(int proxyId) {
        checkProxy("getFatMinX", proxyId);
        return trees[proxies.tree[proxyId]].minX(proxies.node[proxyId]);
    }

    /**
     * The top of a proxy's fat AABB.
     *
     * @param proxyId a live proxy id
     * @return the fat AABB's minimum y
     * @throws IllegalArgumentException if the id is unknown or destroyed
     */
    public float getFatMinY(int proxyId) {
        checkProxy("getFatMinY", proxyId);
        return trees[proxies.tree[proxyId]].minY(proxies.node[proxyId]);
    }

    /**
     * The right of a proxy's fat AABB.
     *
     * @param proxyId a live proxy id
     * @return the fat AABB's maximum x
     * @throws IllegalArgumentException if the id is unknown or destroyed
     */
    public float getFatMaxX(int proxyId) {
        checkProxy("getFatMaxX", proxyId);
        return trees[proxies.tree[proxyId]].maxX(proxies.node[proxyId]);
    }

    /**
     * The bottom of a proxy's fat AABB.
     *
     * @param proxyId a live proxy id
     * @return the fat AABB's maximum y
     * @throws IllegalArgumentException if the id is unknown or destroyed
     */
    public float getFatMaxY(int proxyId) {
        checkProxy("getFatMaxY", proxyId);
        return trees[proxies.tree[proxyId]].maxY(proxies.node[proxyId]);
    }

    /**
     * Whether a proxy is in the move buffer, that is, will have its pairs reported by the next
     * {@link #updatePairs}.
     *
     * @param proxyId a live proxy id
     * @return true if the proxy was created, re-inserted or touched since the last updatePairs
     * @throws IllegalArgumentException if the id is unknown or destroyed
     */
    public boolean isMoved(int proxyId) {
        checkProxy("isMoved", proxyId);
        return moved.contains(proxyId);
    }

    /**
     * The number of live proxies.
     *
     * @return the proxy count
     */
    public int getProxyCount() {
        return proxies.count();
    }

    /**
     * The height of the taller of the two trees (static and dynamic): 0 for an empty tree or a
     * single proxy, otherwise the number of edges on the longest path from the root to a leaf.
     *
     * @return the tree height
     */
    public int getTreeHeight() {
        return Math.max(trees[STATIC_TREE].height(), trees[DYNAMIC_TREE].height());
    }

    /**
     * The number of proxies in the move buffer (each counted once however often it moved).
     *
     * @return the number of proxies whose pairs the next {@link #updatePairs} reports
     */
    public int getMoveCount() {
        return moved.moveCount();
    }

    /**
     * Moves the origin of the coordinate system: every fat AABB is translated by (−dx, −dy), so
     * a point at (dx, dy) moves to (0, 0). Useful to keep float precision in worlds far from the
     * origin; the caller shifts its bodies by the same amount.
     *
     * @param dx the x of the new origin in the old coordinates
     * @param dy the y of the new origin in the old coordinates
     * @throws IllegalArgumentException if dx or dy is NaN or infinite
     * @throws IllegalStateException if called from inside a callback
     */
    public void shiftOrigin(float dx, float dy) {
        checkUnlocked("shiftOrigin");
        BoxChecks.finite("shiftOrigin", "dx", dx);
        BoxChecks.finite("shiftOrigin", "dy", dy);
        trees[STATIC_TREE].shift(dx, dy);
        trees[DYNAMIC_TREE].shift(dx, dy);
    }

    // ------------------------------------------------------------------------------------------
    // Proxy ids and the move buffer

    // ------------------------------------------------------------------------------------------
    // Validation

    /**
     * Checks every invariant of the trees, the proxy table, the free lists and the move buffer.
     * Meant for tests and debugging; it takes time linear in the number of nodes.
     *
     * @throws IllegalStateException describing the first violation found
     */
    public void validate() {
        int leaves = trees[STATIC_TREE].validate("BroadPhase") + trees[DYNAMIC_TREE].validate("BroadPhase");
        checkState(leaves == proxies.count(), "%d leaves but %d proxies", leaves, proxies.count());

        int live = 0;
        boolean[] isLive = new boolean[proxies.highWater()];
        for (int p = 0; p < proxies.highWater(); p++) {
            int node = proxies.node[p];
            if (node == NULL) {
                continue;
            }
            live++;
            isLive[p] = true;
            checkState(proxies.tree[p] == STATIC_TREE || proxies.tree[p] == DYNAMIC_TREE, "proxy %d has tree %d", p,
                    proxies.tree[p]);
            checkState(trees[proxies.tree[p]].holds(node, p), "proxy %d points to node %d, not its leaf", p, node);
        }
        checkState(live == proxies.count(), "%d live proxies, count says %d", live, proxies.count());
        moved.validate(isLive, proxies.highWater());

        proxies.validateFreeList();
    }

    private static void checkState(boolean ok, String format, int a, int b) {
        DynamicTree.check(ok, "BroadPhase", format, a, b);
    }

    // ------------------------------------------------------------------------------------------
    // Argument checks

    private void checkUnlocked(String method) {
        if (lockDepth > 0) {
            throw new IllegalStateException(
                    method + ": the broadphase must not be modified from inside a callback");
        }
    }

    private void checkProxy(String method, int proxyId) {
        if (!proxies.isLive(proxyId)) {
            throw new IllegalArgumentException(
                    method + ": unknown or destroyed proxy id " + proxyId);
        }
    }
}
