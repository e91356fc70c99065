package org.emini.collision;

/**
 * Receives the proxies found by {@link BroadPhase#query}.
 *
 * <p>Implement it once and reuse the instance, so that queries allocate nothing.
 */
public interface QueryCallback {
    /**
     * Called for each proxy whose fat AABB overlaps the query box.
     *
     * <p>The broadphase must not be modified from inside this method; its getters and nested
     * queries may be used.
     *
     * @param proxyId the id of the proxy found
     * @return true to continue the query, false to stop it
     */
    boolean reportProxy(int proxyId);
}
