package org.emini.harness.scenario;

import java.util.List;

/**
 * Flags and initial state of a body, shared by single bodies and generator templates. Defaults are the
 * manual's: dynamic, rotatable, interacting, gravity-affected, no layers, at rest, angle 0.
 *
 * @param isStatic true for a static body
 * @param angle radians (growing angles turn clockwise on the y-down screen)
 * @param vx linear velocity x (px/s)
 * @param vy linear velocity y (px/s)
 * @param angularVelocity rad/s
 * @param rotatable whether the body may rotate
 * @param interacting whether the body collides with other bodies
 * @param gravity whether gravity acts on the body
 * @param layers collision layer bits (0..31)
 * @param sleepingAllowed whether the body may fall asleep when the world lets bodies sleep (default true)
 */
public record BodyState(boolean isStatic, double angle, double vx, double vy, double angularVelocity,
                        boolean rotatable, boolean interacting, boolean gravity, List<Integer> layers,
                        boolean sleepingAllowed) {
    /** The manual's defaults. */
    public static final BodyState DEFAULT = new BodyState(false, 0, 0, 0, 0, true, true, true, List.of(), true);
}
