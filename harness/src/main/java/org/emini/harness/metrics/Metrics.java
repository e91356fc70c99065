package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.List;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.build.UnsupportedElementException;
import org.emini.harness.load.JsonPath;
import org.emini.harness.scenario.MetricSpec;

/** Creates the metric a scene requests; only requested metrics exist, so only they cost time. */
public final class Metrics {
    private Metrics() {
    }

    /**
     * The metrics a scene requests, in order.
     *
     * @throws UnsupportedElementException for a metric the engine cannot feed
     */
    public static List<Metric> create(List<MetricSpec> specs, BuiltWorld world) throws UnsupportedElementException {
        List<Metric> metrics = new ArrayList<>();
        for (MetricSpec m : specs) {
            metrics.add(create(m, world));
        }
        return metrics;
    }

    /**
     * Penetration per pair of bodies over the run so far, deepest first: the penetration metric's, or an
     * empty list when the scene did not compute penetration.
     */
    public static List<PenetrationPair> pairs(List<Metric> metrics) {
        for (Metric m : metrics) {
            if (m instanceof PenetrationMetric p) {
                return p.pairs();
            }
        }
        return List.of();
    }

    /**
     * The metric for a request.
     *
     * @throws UnsupportedElementException for a metric the engine cannot feed
     */
    public static Metric create(MetricSpec spec, BuiltWorld world) throws UnsupportedElementException {
        switch (spec.kind()) {
            case energy:
                return new EnergyMetric(world);
            case linearMomentum:
                return new LinearMomentumMetric(world);
            case angularMomentum:
                return new AngularMomentumMetric(world, spec.aboutX(), spec.aboutY());
            case penetration:
                return new PenetrationMetric(world, spec);
            case tunnelling:
                return new TunnellingMetric(world, spec);
            case stability:
                return new StabilityMetric(world);
            case constraintError:
                return new ConstraintErrorMetric(world.world());
            case jointLimits:
                return new JointLimitsMetric(world.world());
            case particles:
                return new ParticlesMetric(world, spec);
            case sleeping:
                return new SleepingMetric(world);
            default:
                throw new UnsupportedElementException("metric " + spec.kind(),
                        spec.path() != null ? spec.path() : JsonPath.ROOT.key("run"));
        }
    }
}
