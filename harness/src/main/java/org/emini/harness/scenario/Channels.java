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

    /**
     * Per-body quantities: {@code body.NAME.Q}. {@code speed} (|v|), {@code displacement} (distance from the
     * first sample's position) and {@code turn} (angle − the first sample's angle) are derived from the others.
     */
    public static final List<String> BODY_QUANTITIES = List.of("x", "y", "angle", "vx", "vy", "omega", "speed",
            "displacement", "turn");

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

    /** Whether a body name in an expectation is a group: {@code *} stands for any text ({@code box[*]}, {@code wheel*}). */
    public static boolean isGroup(String name) {
        return name != null && name.indexOf('*') >= 0;
    }

    /** Whether a body name matches a group pattern ({@code *} any text, everything else literal). */
    public static boolean matches(String pattern, String name) {
        String[] parts = pattern.split("\\*", -1);
        StringBuilder re = new StringBuilder();
        for (int i = 0; i < parts.length; i++) {
            if (i > 0) {
                re.append(".*");
            }
            re.append(java.util.regex.Pattern.quote(parts[i]));
        }
        return name.matches(re.toString());
    }

    /** The channel name of a body quantity. */
    public static String body(String bodyName, String quantity) {
        return "body." + bodyName + "." + quantity;
    }
}
