/**
 * Collision detection. {@link org.emini.collision.BroadPhase}, dynamic trees of fat bounding boxes
 * (one for static bodies, one for moving ones), finds the pairs of bodies that came close; {@link org.emini.collision.Collider} turns a pair of
 * placed shapes into a {@link org.emini.collision.Manifold} of at most two contact points with a
 * shared normal, including speculative points that still have a small gap.
 *
 * <p>Nothing here allocates per call once its arrays have grown; a world keeps one broadphase and
 * one collider and reuses manifolds.
 */
package org.emini.collision;
