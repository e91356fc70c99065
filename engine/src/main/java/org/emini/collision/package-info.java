/**
 * Collision detection: the engine's internals, not for users (apart from {@link
 * org.emini.collision.QueryCallback}, the callback of the world's queries). These classes are public
 * so that the engine's packages can share them; they may change in any release.
 *
 * <p> {@link org.emini.collision.BroadPhase}, dynamic trees of fat bounding boxes
 * (one for static bodies, one for moving ones), finds the pairs of bodies that came close; {@link org.emini.collision.Collider} turns a pair of
 * placed shapes into a {@link org.emini.collision.Manifold} of at most two contact points with a
 * shared normal, including speculative points that still have a small gap. {@link
 * org.emini.collision.RayCaster} casts a ray against a shape or a segment (the world's ray casts
 * and the particles share it), {@link org.emini.collision.ShapeCaster} sweeps a shape along a
 * translation to its first contact, and {@link org.emini.collision.SweptBox} prunes the trees for
 * both.
 *
 * <p>Nothing here allocates per call once its arrays have grown; a world keeps one broadphase and
 * one collider and reuses manifolds.
 */
package org.emini.collision;
