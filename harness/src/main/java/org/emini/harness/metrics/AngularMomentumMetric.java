package org.emini.harness.metrics;

import java.util.List;
import org.emini.dynamics.Body;
import org.emini.harness.build.BuiltWorld;

/**
 * angularMomentum = Σ I·ω + m·((x − px)·vy − (y − py)·vx) over dynamic bodies, about the point
 * (px, py); positive in the direction of growing angles (the engine's ω).
 */
final class AngularMomentumMetric implements Metric {
    private final Body[] bodies;
    private final double px;
    private final double py;

    AngularMomentumMetric(BuiltWorld built, double px, double py) {
        bodies = DynamicBodies.of(built);
        this.px = px;
        this.py = py;
    }

    @Override
    public List<String> channels() {
        return List.of("angularMomentum");
    }

    @Override
    public void sample(double[] out, int offset) {
        double l = 0;
        for (Body b : bodies) {
            double m = b.getMass();
            l += DynamicBodies.spin(b) + m * ((b.getX() - px) * b.getVelocityY() - (b.getY() - py) * b.getVelocityX());
        }
        out[offset] = l;
    }
}
