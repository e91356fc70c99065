package org.emini.harness.scenario;

import org.emini.harness.load.JsonPath;

/**
 * One outcome the run must reach.
 *
 * @param kind what is checked
 * @param channel the metric or closed-form channel (METRIC, CLOSED_FORM)
 * @param of how samples reduce to one figure (METRIC, CLOSED_FORM); null when {@code at} is used
 * @param at the time whose nearest sample is taken, or NaN
 * @param relative divide drift figures by |initial|
 * @param body the body (ENDS_NEAR, STAYS_INSIDE)
 * @param point ENDS_NEAR target, or STAYS_INSIDE minimum corner
 * @param max STAYS_INSIDE maximum corner
 * @param atMost upper bound, or NaN
 * @param atLeast lower bound, or NaN
 * @param near target value, or NaN (with {@code tolerance})
 * @param tolerance absolute tolerance for {@code near} and ENDS_NEAR, or NaN
 * @param windowFrom start of the time window that counts (s)
 * @param windowUntil end of the time window that counts (s), or +inf
 * @param maxSpeed STABLE speed bound, or NaN
 * @param maxAngularSpeed STABLE angular speed bound, or NaN
 * @param maxEnergyRise STABLE energy rise bound, or NaN
 * @param name a label, or null (a description is generated)
 * @param why where the bound comes from, or null
 * @param knownFailure the known-failure mark, or null
 * @param path where the expectation is written
 * @param crossing the value whose crossings {@code firstCrossing} and {@code period} time, or NaN (period:
 *     the window's mean)
 * @param inOrder a group's first crossings must come in the order the scene creates its bodies
 * @param minus a channel subtracted sample by sample from {@code channel} (body A against body B), or null
 * @param relativeTo a figure (a METRIC expectation without bounds) that multiplies every bound, or null
 * @param minusTrace a stored trace's channel subtracted sample by sample from {@code channel} (this run against a
 *     reference run), or null
 */
public record ExpectationSpec(Kind kind, String channel, String of, double at, boolean relative, String body,
                              double[] point, double[] max, double atMost, double atLeast, double near,
                              double tolerance, double windowFrom, double windowUntil, double maxSpeed,
                              double maxAngularSpeed, double maxEnergyRise, String name, String why,
                              KnownFailure knownFailure, JsonPath path, double crossing, boolean inOrder,
                              String minus, ExpectationSpec relativeTo, ReferenceTrace minusTrace) {

    /** Expectation kinds. */
    public enum Kind { METRIC, CLOSED_FORM, ENDS_NEAR, STAYS_INSIDE, NO_TUNNELLING, STABLE }

    /** The same expectation on one member of its group: the body and the channel's body replaced. */
    public ExpectationSpec forBody(String member) {
        String[] bc = channel != null ? Channels.bodyChannel(channel) : null;
        return new ExpectationSpec(kind, bc != null ? Channels.body(member, bc[1]) : channel, of, at, relative,
                body != null ? member : null, point, max, atMost, atLeast, near, tolerance, windowFrom, windowUntil,
                maxSpeed, maxAngularSpeed, maxEnergyRise, name, why, knownFailure, path, crossing, false, minus, relativeTo,
                minusTrace);
    }

    /** The same expectation with every bound multiplied by {@code r} (for {@code relativeTo}). */
    public ExpectationSpec timesBounds(double r) {
        return new ExpectationSpec(kind, channel, of, at, relative, body, point, max, atMost * r, atLeast * r, near * r,
                tolerance * Math.abs(r), windowFrom, windowUntil, maxSpeed, maxAngularSpeed, maxEnergyRise, name, why,
                knownFailure, path, crossing, inOrder, minus, null, minusTrace);
    }

    /** The group pattern this expectation reads ({@code body: box[*]} or {@code metric: body.box[*].y}), or null. */
    public String group() {
        String[] bc = channel != null ? Channels.bodyChannel(channel) : null;
        String b = bc != null ? bc[0] : body;
        return Channels.isGroup(b) ? b : null;
    }

    /**
     * Whether this expectation reads an extreme of its series ({@code of: max, min, maxAbs, maxDrift},
     * {@code staysInside}, a {@code stable} bound on the energy's rise; the speeds are held between samples
     * by the stability metric): the harness judges those on every tick whatever the scene's sampling.
     * Not one against a stored reference trace, which is matched sample by sample.
     */
    public boolean readsExtremes() {
        if (minusTrace != null) {
            return false;
        }
        return switch (kind) {
            case STAYS_INSIDE -> true;
            case STABLE -> !Double.isNaN(maxEnergyRise);
            case METRIC -> of != null && (of.equals("max") || of.equals("min") || of.equals("maxAbs") || of.equals("maxDrift"));
            default -> false;
        };
    }

    /**
     * The channels the harness records on every tick to judge this expectation ({@link #readsExtremes()}):
     * its own, the one it is measured against ({@code minus}, {@code relativeTo}), its body's position
     * ({@code staysInside}), the energy and speeds of {@code stable}. Empty when it reads no extreme. A
     * body channel may name a group ({@code body.box[*].x}).
     */
    public java.util.List<String> extremeChannels() {
        if (!readsExtremes()) {
            return java.util.List.of();
        }
        java.util.List<String> out = new java.util.ArrayList<>();
        for (String c : new String[] {channel, minus, relativeTo != null ? relativeTo.channel() : null,
            body != null ? Channels.body(body, "x") : null}) {
            if (c != null) {
                out.add(c);
            }
        }
        if (kind == Kind.STABLE) {
            out.add("energy.total");
            out.add("stability.maxSpeed");
        }
        return out;
    }

    /** A short human description, used in reports when the scene gives no name. */
    public String describe() {
        if (name != null) {
            return name;
        }
        StringBuilder out = new StringBuilder();
        switch (kind) {
            case METRIC:
            case CLOSED_FORM:
                out.append(kind == Kind.CLOSED_FORM ? "closedForm " : "").append(channel)
                        .append(minus != null ? " − " + minus : "")
                        .append(minusTrace != null ? " − " + minusTrace.channel() + " of " + minusTrace.file() : "").append(' ')
                        .append(of != null ? of : "at " + at + " s");
                if (relative) {
                    out.append(" (relative)");
                }
                if (!Double.isNaN(near)) {
                    out.append(" near ").append(near).append(" ± ").append(tolerance);
                }
                if (!Double.isNaN(atLeast)) {
                    out.append(" ≥ ").append(atLeast);
                }
                if (!Double.isNaN(atMost)) {
                    out.append(" ≤ ").append(atMost);
                }
                if (relativeTo != null) {
                    out.append(" × ").append(relativeTo.describe());
                }
                break;
            case ENDS_NEAR:
                out.append(body).append(" ends within ").append(tolerance).append(" px of (")
                        .append(point[0]).append(", ").append(point[1]).append(')');
                break;
            case STAYS_INSIDE:
                out.append(body).append(" stays inside (").append(point[0]).append(", ").append(point[1])
                        .append(")..(").append(max[0]).append(", ").append(max[1]).append(')');
                break;
            case NO_TUNNELLING:
                out.append("no tunnelling");
                break;
            default:
                out.append("stable");
                break;
        }
        return out.toString();
    }
}
