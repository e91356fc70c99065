package org.emini.harness.oracle;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.regex.Pattern;
import org.emini.harness.scenario.Section;

/**
 * A scene's {@code reference.oracle} section (scenarios/README.md, References): how the comparison with
 * pymunk treats it.
 *
 * @param chaotic trajectories diverge by nature: compare aggregates only (no trajectory rows)
 * @param continuousCollision the scene tests continuous collision, which pymunk lacks: rows with a
 *     reference are judged against it, not by agreement with pymunk
 * @param skip why the oracle cannot run the scene, or null
 * @param tolerances absolute tolerance on the engine–oracle difference, by channel name or glob
 *     ({@code body.*.x}); channels not listed get {@link Comparison#defaultTolerance}
 * @param windowFrom first time (s) whose samples count
 * @param windowUntil last time (s) whose samples count
 */
public record OracleSettings(boolean chaotic, boolean continuousCollision, String skip,
                             Map<String, Double> tolerances, double windowFrom, double windowUntil) {

    /** The settings of a scene without a reference.oracle section. */
    public static final OracleSettings DEFAULT = new OracleSettings(false, false, null, Map.of(), 0,
            Double.POSITIVE_INFINITY);

    /** The same settings for an oracle that has continuous collision (Box2D): its rows are judged for agreement. */
    public OracleSettings withoutContinuousCollision() {
        return new OracleSettings(chaotic, false, skip, tolerances, windowFrom, windowUntil);
    }

    /** Reads the section (null: the defaults). */
    public static OracleSettings of(Section section) {
        if (section == null) {
            return DEFAULT;
        }
        JsonNode n = section.node();
        Map<String, Double> tolerances = new LinkedHashMap<>();
        if (n.has("tolerances")) {
            n.get("tolerances").fields().forEachRemaining(e -> tolerances.put(e.getKey(), e.getValue().asDouble()));
        }
        JsonNode w = n.get("window");
        return new OracleSettings(n.path("chaotic").asBoolean(false), n.path("continuousCollision").asBoolean(false),
                n.has("skip") ? n.get("skip").asText() : null, tolerances,
                w != null ? w.get(0).asDouble() : 0, w != null ? w.get(1).asDouble() : Double.POSITIVE_INFINITY);
    }

    /** The scene's tolerance for a channel (an exact name first, then the first matching glob), or NaN. */
    public double tolerance(String channel) {
        Double exact = tolerances.get(channel);
        if (exact != null) {
            return exact;
        }
        for (Map.Entry<String, Double> e : tolerances.entrySet()) {
            if (e.getKey().contains("*") && glob(e.getKey()).matcher(channel).matches()) {
                return e.getValue();
            }
        }
        return Double.NaN;
    }

    private static Pattern glob(String g) {
        StringBuilder re = new StringBuilder();
        for (String part : g.split("\\*", -1)) {
            if (re.length() > 0) {
                re.append(".*");
            }
            re.append(Pattern.quote(part));
        }
        return Pattern.compile(re.toString());
    }

    /** Whether a sample time counts. */
    public boolean inWindow(double t) {
        return t >= windowFrom - 1e-9 && t <= windowUntil + 1e-9;
    }
}
