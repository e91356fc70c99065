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

    /** The name of the landscape as one party of a penetration pair ({@code between: [ball, landscape]}). */
    public static final String LANDSCAPE = "landscape";

    /** The penetration channels a pair filter ({@code between}) narrows: the quantities after {@code penetration.}. */
    public static final List<String> PAIR_QUANTITIES = List.of("max", "mean", "points");

    /**
     * The channel of a penetration quantity narrowed to the pairs between two bodies or groups:
     * {@code penetration.max(box[*], ground)}.
     */
    public static String pair(String quantity, String a, String b) {
        return "penetration." + quantity + "(" + a + ", " + b + ")";
    }

    /**
     * A channel without its pair filter: {@code penetration.max(box[*], ground)} gives {@code penetration.max};
     * any other channel is returned as it is.
     */
    public static String base(String channel) {
        int open = channel.indexOf('(');
        return channel.startsWith("penetration.") && open > 0 && channel.endsWith(")") ? channel.substring(0, open) : channel;
    }

    /** Whether a channel is a penetration quantity narrowed to pairs ({@link #pair}). */
    public static boolean isPair(String channel) {
        return !base(channel).equals(channel);
    }

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
