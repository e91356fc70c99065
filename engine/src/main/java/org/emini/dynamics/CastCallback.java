package org.emini.dynamics;

/**
 * Receives each hit of {@link Simulation#rayCast} and {@link Simulation#castShape}, and steers the
 * cast by its answer as Box2D's {@code b2CastResultFcn} does. Implement it once and reuse the
 * instance, so that casts allocate nothing.
 */
public interface CastCallback {
    /**
     * Called for each part of a body, and each landscape segment, that the cast hits at or before
     * its current end.
     *
     * @param hit the hit; it belongs to the world and is valid only during this call
     *     ({@link CastHit#set(CastHit)} copies it)
     * @return what to do next: 0 stops the cast; a fraction in (0, 1] no larger than the current
     *     one clips the cast there (later hits must be at or before it: return the hit's fraction
     *     to end up with the closest hit); a negative value (−1) ignores this hit and goes on;
     *     1, or anything larger than the current end, goes on unchanged. NaN is an error.
     */
    float reportHit(CastHit hit);
}
