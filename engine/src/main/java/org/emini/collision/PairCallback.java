package org.emini.collision;

/**
 * Receives the potentially colliding pairs found by {@link BroadPhase#updatePairs(PairCallback)}.
 *
 * <p>Implement it once (for example on the contact manager) and reuse the instance every step, so
 * that pair generation allocates nothing.
 */
public interface PairCallback {
    /**
     * Called once per pair of proxies whose fat AABBs overlap.
     *
     * <p>The broadphase must not be modified (proxies created, moved, touched or destroyed) from
     * inside this method; its getters and {@link BroadPhase#query} may be used.
     *
     * @param userDataA the user data of the proxy with the smaller id
     * @param userDataB the user data of the proxy with the larger id
     */
    void addPair(int userDataA, int userDataB);

    /**
     * Whether the receiver already has this pair (a contact for it, say), asked while the pairs are
     * collected: a known pair is neither collected nor reported, and does not count towards the pair
     * limit. A moving shape's pairs are mostly ones it had before, and collecting them only to be
     * skipped in {@link #addPair} costs a sort of all of them. Called in no particular order, before
     * any {@link #addPair} of the same update; it must not modify the broadphase. Default: none is
     * known.
     *
     * @param userDataA the user data of one proxy
     * @param userDataB the user data of the other
     * @return true to leave the pair out
     */
    default boolean isKnownPair(int userDataA, int userDataB) {
        return false;
    }
}
