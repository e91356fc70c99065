package org.emini.bench.engine;

import org.emini.harness.scenario.Scenario;

/**
 * One physics engine behind the benchmark: builds a world from a loaded scene, ticks it, and reports
 * the bodies' poses in the scene's units (px, y down the screen, angles growing clockwise), so every
 * engine is judged by the same stability check.
 */
public interface BenchEngine extends AutoCloseable {

    /** The engine's id in results: {@code emini}, {@code dyn4j}, {@code jbox2d}, {@code gdx-box2d}. */
    String id();

    /**
     * Builds the world of a scene.
     *
     * @throws UnsupportedSceneException if the scene uses something this adapter (or engine) lacks
     */
    void build(Scenario scenario) throws UnsupportedSceneException;

    /** One timestep of the scene. */
    void tick();

    /** Number of bodies, in scene order (static ones included). */
    int bodyCount();

    /**
     * Writes x, y (px) and angle (rad) of every body, in scene order, to {@code out[3 i]},
     * {@code out[3 i + 1]}, {@code out[3 i + 2]}.
     */
    void poses(double[] out);

    /** Writes the speed (px/s) of every body, in scene order, to {@code out[i]}. */
    void speeds(double[] out);

    /**
     * Writes the angular velocity (rad/s, in the scene's sense: positive grows the angle, clockwise
     * on the screen) of every body, in scene order, to {@code out[i]}.
     */
    void angularVelocities(double[] out);

    /**
     * Live particles: Emini's particles, or the circle bodies the peers make for them (not counted
     * in {@link #bodyCount()}).
     */
    default int particleCount() {
        return 0;
    }

    /** Writes x, y (px) of every live particle to {@code out[2 i]}, {@code out[2 i + 1]}. */
    default void particlePositions(double[] out) {
    }

    /**
     * Dynamic bodies the engine has put to sleep (scenes with {@code world.sleeping}), or -1 when the
     * scene does not let bodies sleep.
     */
    default int sleepingCount() {
        return -1;
    }

    /** The engine's settings as used, for the report (timestep, iterations, unit scale, ...). */
    String settings();

    @Override
    void close();
}
