package org.emini.harness.scenario;

/**
 * The world's sleeping setting ({@code world.sleeping}): whether bodies may fall asleep, and the
 * engine's tolerances where the scene gives them (NaN: the engine's default).
 *
 * @param enabled whether sleeping is on (the engine's default is off)
 * @param linearTolerance px/s below which a body rests, or NaN
 * @param angularTolerance rad/s below which a body rests, or NaN
 * @param timeToSleep seconds an island must rest before it sleeps, or NaN
 */
public record SleepSpec(boolean enabled, double linearTolerance, double angularTolerance, double timeToSleep) {
    /** Sleeping off, the engine's (and the original manual's) default. */
    public static final SleepSpec OFF = new SleepSpec(false, Double.NaN, Double.NaN, Double.NaN);

    /** The same tolerances, switched on or off (the harness's {@code --sleeping on|off}). */
    public SleepSpec switched(boolean on) {
        return new SleepSpec(on, linearTolerance, angularTolerance, timeToSleep);
    }
}
