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
}
