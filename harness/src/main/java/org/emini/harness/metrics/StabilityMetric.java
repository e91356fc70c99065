package org.emini.harness.metrics;

import java.util.List;
import org.emini.dynamics.Body;
import org.emini.harness.build.BuiltWorld;

/**
 * Watched after every tick, reported per sample as the worst value since the previous sample:
 * stability.maxSpeed = the largest |v| of a dynamic body; stability.maxAngularSpeed = the largest |ω|;
 * stability.nonFinite = the largest number of dynamic bodies with a NaN or infinite position, angle or
 * velocity in one tick.
 */
final class StabilityMetric implements Metric {
    private final Body[] bodies;
    private double maxSpeed;
    private double maxAngularSpeed;
    private int nonFinite;

    StabilityMetric(BuiltWorld built) {
        bodies = DynamicBodies.of(built);
        afterTick();
    }

    @Override
    public List<String> channels() {
        return List.of("stability.maxSpeed", "stability.maxAngularSpeed", "stability.nonFinite");
    }

    @Override
    public void afterTick() {
        int bad = 0;
        for (Body b : bodies) {
            double vx = b.getVelocityX();
            double vy = b.getVelocityY();
            double w = b.getAngularVelocity();
            if (!Double.isFinite(b.getX()) || !Double.isFinite(b.getY()) || !Double.isFinite(b.getAngle())
                    || !Double.isFinite(vx) || !Double.isFinite(vy) || !Double.isFinite(w)) {
                bad++;
                continue;
            }
            maxSpeed = Math.max(maxSpeed, Math.sqrt(vx * vx + vy * vy));
            maxAngularSpeed = Math.max(maxAngularSpeed, Math.abs(w));
        }
        nonFinite = Math.max(nonFinite, bad);
    }

    @Override
    public void sample(double[] out, int offset) {
        out[offset] = maxSpeed;
        out[offset + 1] = maxAngularSpeed;
        out[offset + 2] = nonFinite;
        maxSpeed = 0;
        maxAngularSpeed = 0;
        nonFinite = 0;
        afterTick();
    }
}
