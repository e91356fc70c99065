package org.emini.harness.scenario;

import org.emini.harness.load.JsonPath;

/**
 * Something done to the world at a time. It is applied before the first tick whose start time is at
 * or after {@code at}; forces and torques are applied before each tick that starts within
 * [at, at + duration), one tick when no duration is given.
 *
 * @param at seconds from the start
 * @param kind what to do
 * @param body the body acted on (null for gravity and emit)
 * @param vector impulse, force, velocity or gravity, by kind (null if not given)
 * @param point world point of application, or null for the body's centre
 * @param value angular impulse, torque, angular velocity or particle count (emit), by kind (NaN if not given)
 * @param duration seconds, or NaN for one tick
 * @param emitter the emitter of an emit action (its scene name), else null
 * @param path where the action is written
 */
public record ActionSpec(double at, Kind kind, String body, double[] vector, double[] point, double value,
                         double duration, String emitter, JsonPath path) {

    /** Action kinds, named as in the scene files. */
    public enum Kind { impulse, angularImpulse, force, torque, velocity, gravity, emit }
}
