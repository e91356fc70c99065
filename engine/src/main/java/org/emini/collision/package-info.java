/**
 * Narrowphase collision: {@link org.emini.collision.Collider} turns a pair of placed shapes into a
 * {@link org.emini.collision.Manifold} of at most two contact points with a shared normal,
 * including speculative points that still have a small gap.
 *
 * <p>Nothing here allocates per call; a world keeps one collider and reuses manifolds.
 */
package org.emini.collision;
