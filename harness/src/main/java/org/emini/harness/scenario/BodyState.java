package org.emini.harness.scenario;

import java.util.List;

/**
 * Flags and initial state of a body, shared by single bodies and generator templates. Defaults are the
 * manual's: dynamic, rotatable, interacting, gravity-affected, no layers, at rest, angle 0, and Box2D's
 * filter defaults (category bit 0, every mask bit, group 0).
 *
 * @param isStatic true for a static body
 * @param kinematic true for a kinematic body (moved by its velocity alone; never with isStatic)
 * @param angle radians (growing angles turn clockwise on the y-down screen)
 * @param vx linear velocity x (px/s)
 * @param vy linear velocity y (px/s)
 * @param angularVelocity rad/s
 * @param rotatable whether the body may rotate
 * @param interacting whether the body collides with other bodies
 * @param gravity whether gravity acts on the body
 * @param layers collision layer bits (0..31)
 * @param categoryBits Box2D's category bits
 * @param maskBits Box2D's mask bits
 * @param group Box2D's group index
 * @param sleepingAllowed whether the body may fall asleep when the world lets bodies sleep (default true)
 * @param sensor whether the body is a sensor: collides with nothing, reports what overlaps it (default false)
 */
public record BodyState(boolean isStatic, boolean kinematic, double angle, double vx, double vy, double angularVelocity,
                        boolean rotatable, boolean interacting, boolean gravity, List<Integer> layers,
                        int categoryBits, int maskBits, int group, boolean sleepingAllowed,
                        boolean sensor) {
    /** The category bits of a body that gives none: bit 0. */
    public static final int DEFAULT_CATEGORY_BITS = 1;
    /** The mask bits of a body that gives none: all. */
    public static final int DEFAULT_MASK_BITS = -1;
    /** The manual's defaults. */
    public static final BodyState DEFAULT = new BodyState(false, false, 0, 0, 0, 0, true, true, true, List.of(),
            DEFAULT_CATEGORY_BITS, DEFAULT_MASK_BITS, 0, true, false);

    /**
     * The same state at another angle.
     *
     * @param a the angle (radians)
     * @return the state turned to a
     */
    public BodyState withAngle(double a) {
        return new BodyState(isStatic, kinematic, a, vx, vy, angularVelocity, rotatable, interacting, gravity, layers,
                categoryBits, maskBits, group, sleepingAllowed, sensor);
    }

    /**
     * Whether the filter is Box2D's default (and so changes nothing).
     *
     * @return true for category bit 0, every mask bit and group 0
     */
    public boolean defaultFilter() {
        return categoryBits == DEFAULT_CATEGORY_BITS && maskBits == DEFAULT_MASK_BITS && group == 0;
    }
}
