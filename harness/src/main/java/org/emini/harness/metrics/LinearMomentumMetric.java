package org.emini.harness.metrics;

import java.util.List;
import org.emini.dynamics.Body;
import org.emini.harness.build.BuiltWorld;

/** momentum.x, momentum.y = Σ m·v over dynamic bodies. */
final class LinearMomentumMetric implements Metric {
    private final Body[] bodies;

    LinearMomentumMetric(BuiltWorld built) {
        bodies = DynamicBodies.of(built);
    }

    @Override
    public List<String> channels() {
        return List.of("momentum.x", "momentum.y");
    }

    @Override
    public void sample(double[] out, int offset) {
        double px = 0;
        double py = 0;
        for (Body b : bodies) {
            px += (double) b.getMass() * b.getVelocityX();
            py += (double) b.getMass() * b.getVelocityY();
        }
        out[offset] = px;
        out[offset + 1] = py;
    }
}
