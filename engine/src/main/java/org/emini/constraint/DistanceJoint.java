package org.emini.constraint;

import org.emini.dynamics.Body;
import org.emini.dynamics.SolverStep;
import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * Keeps the distance between an anchor on each body at a length, or within a range: a rigid rod
 * (the default), a rope (slack below its length, taut at it: {@link #rope}), a spring toward the
 * length with hard stops at the range's ends, or a free range. The bodies turn freely about the
 * anchors. Box2D's {@code DistanceJoint} (and the older {@code RopeJoint}); pymunk's SlideJoint
 * (a range) and DampedSpring.
 *
 * <p>The range's ends are one-sided rows that close a gap within a substep without crossing it, so
 * a rope never stretches beyond its length by more than the joint softness lets it sag; the
 * spring is soft (its frequency and damping ratio hold whatever the masses), stable at any
 * frequency. Unlike {@link Spring}, whose rigid rod is the manual's, this joint reads its
 * settings the way Box2D does.
 *
 * <p>Example, a 120 px rope from a ceiling to a ball:
 * <pre>{@code
 * DistanceJoint rope = DistanceJoint.rope(ceiling, ball, 0f, 0f, 0f, 0f, 120f);
 * world.addConstraint(rope);
 * }</pre>
 */
public final class DistanceJoint extends TwoBodyConstraint {
    /** Anchors closer than this have no direction: the joint then does nothing (as Spring). */
    private static final float MIN_LENGTH = 1e-4f;

    private final LinearAxis axis = new LinearAxis(this);
    private float length;
    private boolean ranged;
    private boolean active;
    // The anchors' distance at the last line().
    private float current;
    private float tension;

    /**
     * Creates a rigid distance joint whose length is the anchors' distance now.
     *
     * @param a the first body
     * @param b the second body
     * @param ax x of the anchor in a's own frame (px)
     * @param ay y of the anchor in a's own frame (px)
     * @param bx x of the anchor in b's own frame (px)
     * @param by y of the anchor in b's own frame (px)
     */
    public DistanceJoint(Body a, Body b, float ax, float ay, float bx, float by) {
        super("DistanceJoint", a, b, ax, ay, bx, by);
        length = getCurrentLength();
        axis.lock(length);
    }

    /**
     * Creates a rope: no force while the anchors are closer than the length, taut at it.
     *
     * @param a the first body
     * @param b the second body
     * @param ax x of the anchor in a's own frame (px)
     * @param ay y of the anchor in a's own frame (px)
     * @param bx x of the anchor in b's own frame (px)
     * @param by y of the anchor in b's own frame (px)
     * @param maxLength the rope's length (px), &gt; 0
     * @return the joint (not yet added to the world)
     */
    public static DistanceJoint rope(Body a, Body b, float ax, float ay, float bx, float by, float maxLength) {
        Check.positive("DistanceJoint.rope", "maxLength", maxLength);
        DistanceJoint j = new DistanceJoint(a, b, ax, ay, bx, by);
        j.setLength(maxLength);
        j.setLengthRange(0f, maxLength);
        return j;
    }

    /**
     * The distance between the anchors where the bodies are now.
     *
     * @return d (px)
     */
    public float getCurrentLength() {
        float dx = getAnchorBX() - getAnchorAX();
        float dy = getAnchorBY() - getAnchorAY();
        return EMath.sqrt(dx * dx + dy * dy);
    }

    /**
     * The length a rigid joint holds and a spring pulls toward.
     *
     * @return the length (px)
     */
    public float getLength() {
        return length;
    }

    /**
     * Sets the length a rigid joint holds and a spring pulls toward.
     *
     * @param length the length (px), &ge; 0
     */
    public void setLength(float length) {
        this.length = Check.nonNegative("DistanceJoint.setLength", "length", length);
        axis.setSpringTarget("DistanceJoint.setLength", length);
        if (!ranged && !axis.isSpringEnabled()) {
            axis.lock(length);
        }
    }

    /**
     * Lets the distance move freely within [min, max] (pulled toward the length if a spring is set),
     * with hard stops at both ends: min 0 and max the length make a rope.
     *
     * @param min the shortest distance (px), &ge; 0
     * @param max the longest (px), &ge; min
     */
    public void setLengthRange(float min, float max) {
        Check.nonNegative("DistanceJoint.setLengthRange", "min", min);
        axis.setLimits("DistanceJoint.setLengthRange", min, max);
        ranged = true;
        axis.unlock();
    }

    /**
     * The shortest distance allowed.
     *
     * @return min (px), or the length when rigid without a range
     */
    public float getMinLength() {
        return ranged ? axis.getLower() : (axis.isSpringEnabled() ? 0f : length);
    }

    /**
     * The longest distance allowed.
     *
     * @return max (px), or the length when rigid, infinite for a spring without a range
     */
    public float getMaxLength() {
        return ranged ? axis.getUpper() : (axis.isSpringEnabled() ? Float.POSITIVE_INFINITY : length);
    }

    /**
     * Makes the joint a spring toward the length (within the range, if one is set).
     *
     * @param hertz the natural frequency (Hz), &ge; 0; 0 exerts no spring force
     * @param dampingRatio the damping ratio, &ge; 0 (1 is critical)
     */
    public void setSpring(float hertz, float dampingRatio) {
        axis.setSpring("DistanceJoint.setSpring", hertz, dampingRatio);
        axis.setSpringTarget("DistanceJoint.setSpring", length);
        axis.unlock();
    }

    /**
     * Whether the joint holds its length rigidly (no range and no spring).
     *
     * @return true when rigid
     */
    public boolean isRigid() {
        return !ranged && !axis.isSpringEnabled();
    }

    /**
     * The force along the anchor line in the last tick, averaged over it: positive when the joint
     * pulls the bodies together (a taut rope), negative when it pushes them apart.
     *
     * @return the tension (mass·px/s²)
     */
    public float getTension() {
        return tension;
    }

    /**
     * Points the axis along the anchor line B − A now, with the arms' cross products.
     *
     * @return the inverse effective mass along it, or 0 when the anchors meet (no direction)
     */
    private float line() {
        float len = EMath.sqrt(sepX * sepX + sepY * sepY);
        if (len < MIN_LENGTH) {
            return 0f;
        }
        float ux = sepX / len;
        float uy = sepY / len;
        float k = axis.set(ux, uy, rAx * uy - rAy * ux, rBx * uy - rBy * ux);
        axis.setInverseMass(k);
        current = len;
        return k;
    }

    @Override
    public void prepare(SolverStep step) {
        active = prepareAnchors(step);
        arms(step);
        axis.prepare(line(), 1f, step);
    }

    @Override
    public void warmStart(SolverStep step) {
        if (!active) {
            return;
        }
        float scale = substepScale(step);
        arms(step);
        if (line() > 0f) {
            axis.warmStart(step, scale);
        }
    }

    @Override
    public float solve(SolverStep step, boolean useBias) {
        if (!active) {
            return 0f;
        }
        arms(step);
        return line() > 0f ? axis.solve(step, useBias, current) : 0f;
    }

    @Override
    public void finish(SolverStep step) {
        axis.finish(step.getTimestep());
        tension = -axis.getForce();
        force = Math.abs(tension);
    }

    @Override
    public String toString() {
        return "DistanceJoint(" + bodyA + ", " + bodyB + ", length " + length + (isRigid() ? ", rigid)" : ")");
    }
}
