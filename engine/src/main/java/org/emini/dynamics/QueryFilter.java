package org.emini.dynamics;

/**
 * Chooses what a closest-hit cast ({@link Simulation#rayCastClosest},
 * {@link Simulation#castShapeClosest}) may find; the all-hit casts filter in their
 * {@link CastCallback} (−1 ignores a hit), the point and overlap queries in their callbacks. To
 * skip the bodies that share a collision layer bit with {@code bits}, as the engine's collisions do:
 * {@code (body, segment) -> body == null || (body.getCollisionLayers() & bits) == 0}.
 */
public interface QueryFilter {
    /**
     * Whether a body, or a landscape segment, may be found.
     *
     * @param body the body, or null for a landscape segment
     * @param segment the segment's index in the world's {@link Landscape}, or −1 for a body
     * @return true to test it, false to look through it
     */
    boolean accepts(Body body, int segment);
}
