package org.emini.harness.closedform;

/**
 * A closed-form (or exactly integrable) model of a scene: the physics the engine should approximate.
 * It predicts some channels as functions of time; the harness compares the run with it, and issues 6
 * and 7 measure the engine's and the oracle's error against it.
 */
public interface ClosedForm {
    /**
     * The predicted value of a channel at a time.
     *
     * @param channel a channel name ({@code body.ball.y}, {@code momentum.x})
     * @param t seconds from the start
     * @return the value, or NaN when the model does not predict this channel
     */
    double predict(String channel, double t);
}
