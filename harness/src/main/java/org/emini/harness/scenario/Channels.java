package org.emini.harness.scenario;

import java.util.List;
import java.util.Map;

/**
 * Names of the scalar series ("channels") that metrics produce, as used in traces and expectations.
 * Each metric's channels are defined in scenarios/README.md.
 */
public final class Channels {
    private Channels() {
    }

    /** Per-body quantities: {@code body.NAME.Q}. */
    public static final List<String> BODY_QUANTITIES = List.of("x", "y", "angle", "vx", "vy", "omega", "speed");

    /** The channels each metric produces, in trace order. */
    public static final Map<MetricSpec.Kind, List<String>> OF_METRIC = Map.of(
            MetricSpec.Kind.energy, List.of("energy.kinetic", "energy.potential", "energy.total"),
            MetricSpec.Kind.linearMomentum, List.of("momentum.x", "momentum.y"),
            MetricSpec.Kind.angularMomentum, List.of("angularMomentum"),
            MetricSpec.Kind.penetration, List.of("penetration.max", "penetration.mean", "penetration.points"),
            MetricSpec.Kind.constraintError, List.of("constraintError.max", "constraintError.mean"),
            MetricSpec.Kind.tunnelling, List.of("tunnelling.count"),
            MetricSpec.Kind.stability, List.of("stability.maxSpeed", "stability.maxAngularSpeed", "stability.nonFinite"),
            MetricSpec.Kind.particles, List.of("particles.count", "particles.outside"),
            MetricSpec.Kind.sleeping, List.of("sleeping.count", "sleeping.fraction"),
            MetricSpec.Kind.jointLimits, List.of("jointLimits.angle", "jointLimits.translation"));

    /** The metric producing a channel, or null for a body channel or an unknown name. */
    public static MetricSpec.Kind metricOf(String channel) {
        for (Map.Entry<MetricSpec.Kind, List<String>> e : OF_METRIC.entrySet()) {
            if (e.getValue().contains(channel)) {
                return e.getKey();
            }
        }
        return null;
    }

    /** For {@code body.NAME.Q}: {NAME, Q}; otherwise null. */
    public static String[] bodyChannel(String channel) {
        if (!channel.startsWith("body.")) {
            return null;
        }
        int dot = channel.lastIndexOf('.');
        if (dot <= 5) {
            return null;
        }
        String quantity = channel.substring(dot + 1);
        return BODY_QUANTITIES.contains(quantity) ? new String[] {channel.substring(5, dot), quantity} : null;
    }

    /** The channel name of a body quantity. */
    public static String body(String bodyName, String quantity) {
        return "body." + bodyName + "." + quantity;
    }
}
