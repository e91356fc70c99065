package org.emini.harness.closedform;

import java.util.ArrayList;
import java.util.List;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Channels;

/**
 * Models {@code bouncingBall}: a ball falling under g (down the screen) onto a floor where its centre is
 * at restY, leaving each impact at e times its impact speed: apex heights fall as e^(2n)·h0 and the
 * bounces end after √(2h0/g)·(1 + e)/(1 − e). Predicts y and vy of the ball.
 */
final class BouncingBall implements ClosedForm {
    private final String body;
    private final double g, restY;
    // Each flight: start time, start y, start vy.
    private final List<double[]> flights = new ArrayList<>();

    BouncingBall(BodySpec b, double g, double restY, double e) {
        body = b.name();
        this.g = g;
        this.restY = restY;
        double t = 0;
        double y = b.y();
        double vy = b.state().vy();
        for (int i = 0; i < 10_000; i++) {
            flights.add(new double[] {t, y, vy});
            // Solve y + vy·τ + ½·g·τ² = restY for the positive root (y < restY: above the floor).
            double disc = vy * vy + 2 * g * (restY - y);
            double tau = (-vy + Math.sqrt(Math.max(0, disc))) / g;
            double impact = vy + g * tau;
            t += tau;
            y = restY;
            vy = -e * impact;
            if (Math.abs(vy) < 1e-9 || tau < 1e-12) {
                flights.add(new double[] {t, restY, 0});
                break;
            }
        }
    }

    @Override
    public double predict(String channel, double t) {
        String[] bc = Channels.bodyChannel(channel);
        if (bc == null || !bc[0].equals(body)) {
            return Double.NaN;
        }
        double[] f = flights.get(0);
        for (double[] candidate : flights) {
            if (candidate[0] <= t) {
                f = candidate;
            }
        }
        boolean resting = f == flights.get(flights.size() - 1) && f[2] == 0 && f[1] == restY;
        double tau = t - f[0];
        switch (bc[1]) {
            case "y": return resting ? restY : f[1] + f[2] * tau + 0.5 * g * tau * tau;
            case "vy": return resting ? 0 : f[2] + g * tau;
            default: return Double.NaN;
        }
    }
}
