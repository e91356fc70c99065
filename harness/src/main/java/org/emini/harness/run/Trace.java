package org.emini.harness.run;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.emini.harness.metrics.PenetrationPair;
import org.emini.harness.scenario.Channels;

/**
 * The sampled run: for each sample its tick and time and one value per channel. Channels are the
 * recorded bodies' quantities ({@code body.NAME.x}, y, angle, vx, vy, omega) followed by the metric
 * channels. Written to disk by the trace writer in the format of harness/README.md.
 */
public final class Trace {
    /** The per-body quantities stored for every recorded body, in order. */
    public static final List<String> BODY_FIELDS = List.of("x", "y", "angle", "vx", "vy", "omega");

    private final List<String> bodies;
    private final List<String> metricChannels;
    private final List<String> channels = new ArrayList<>();
    private final Map<String, Integer> index = new HashMap<>();
    private final List<double[]> rows = new ArrayList<>();
    private final List<Long> ticks = new ArrayList<>();
    private final double timestep;
    /** Per sample, whether each recorded body slept; null when the run did not let bodies sleep. */
    private final List<boolean[]> asleep;
    /** Penetration per pair of bodies over the run, deepest first; empty without the penetration metric. */
    private List<PenetrationPair> penetrationPairs = List.of();

    /**
     * @param timestep seconds per tick (time of a sample = tick × timestep)
     * @param bodies names of the recorded bodies
     * @param metricChannels metric channels, in order
     */
    public Trace(double timestep, List<String> bodies, List<String> metricChannels) {
        this(timestep, bodies, metricChannels, false);
    }

    /**
     * @param timestep seconds per tick (time of a sample = tick × timestep)
     * @param bodies names of the recorded bodies
     * @param metricChannels metric channels, in order
     * @param sleeping whether each sample also says which recorded bodies slept (a world that lets
     *     bodies sleep); not a channel: expectations read the {@code sleeping} metric
     */
    public Trace(double timestep, List<String> bodies, List<String> metricChannels, boolean sleeping) {
        this.timestep = timestep;
        this.asleep = sleeping ? new ArrayList<>() : null;
        this.bodies = List.copyOf(bodies);
        this.metricChannels = List.copyOf(metricChannels);
        for (String b : bodies) {
            for (String f : BODY_FIELDS) {
                add(Channels.body(b, f));
            }
        }
        metricChannels.forEach(this::add);
    }

    private void add(String channel) {
        index.put(channel, channels.size());
        channels.add(channel);
    }

    /** Appends a sample; {@code row} has one value per channel, in channel order. */
    public void add(long tick, double[] row) {
        if (row.length != channels.size()) {
            throw new IllegalArgumentException("row of " + row.length + " values for " + channels.size() + " channels");
        }
        if (asleep != null) {
            throw new IllegalArgumentException("this trace records sleeping: give which bodies slept");
        }
        ticks.add(tick);
        rows.add(row);
    }

    /**
     * Appends a sample of a trace that records sleeping.
     *
     * @param row one value per channel, in channel order
     * @param sleeping one flag per recorded body, in order: whether it slept
     */
    public void add(long tick, double[] row, boolean[] sleeping) {
        if (asleep == null) {
            throw new IllegalArgumentException("this trace does not record sleeping");
        }
        if (row.length != channels.size() || sleeping.length != bodies.size()) {
            throw new IllegalArgumentException("row of " + row.length + " values and " + sleeping.length
                    + " sleeping flags for " + channels.size() + " channels and " + bodies.size() + " bodies");
        }
        ticks.add(tick);
        rows.add(row);
        asleep.add(sleeping);
    }

    /** Penetration per pair of bodies over the run, deepest first (empty without the penetration metric). */
    public List<PenetrationPair> penetrationPairs() {
        return penetrationPairs;
    }

    /** Sets the run's penetration per pair (after the run, or as read from a trace file). */
    public void setPenetrationPairs(List<PenetrationPair> pairs) {
        penetrationPairs = List.copyOf(pairs);
    }

    /** Whether the samples say which bodies slept. */
    public boolean recordsSleeping() {
        return asleep != null;
    }

    /** Whether recorded body {@code body} (its index in {@link #bodies()}) slept at sample i. */
    public boolean sleeping(int i, int body) {
        return asleep != null && asleep.get(i)[body];
    }

    /** Every channel, bodies first. */
    public List<String> channels() {
        return Collections.unmodifiableList(channels);
    }

    /** The recorded bodies. */
    public List<String> bodies() {
        return bodies;
    }

    /** The metric channels. */
    public List<String> metricChannels() {
        return metricChannels;
    }

    /** Seconds per tick. */
    public double timestep() {
        return timestep;
    }

    /** Number of samples. */
    public int size() {
        return rows.size();
    }

    /** The tick of sample i. */
    public long tick(int i) {
        return ticks.get(i);
    }

    /** The time of sample i (s). */
    public double time(int i) {
        return ticks.get(i) * timestep;
    }

    /** Whether a channel (including the derived body.NAME.speed, .displacement and .turn) can be read. */
    public boolean has(String channel) {
        if (index.containsKey(channel)) {
            return true;
        }
        String[] bc = Channels.bodyChannel(channel);
        return bc != null && index.containsKey(Channels.body(bc[0], "x"))
                && (bc[1].equals("speed") || bc[1].equals("displacement") || bc[1].equals("turn"));
    }

    /**
     * The values of a channel over the samples; body.NAME.speed is derived from vx and vy, .displacement
     * (the distance from the first sample's position) from x and y, .turn (angle − the first sample's) from
     * angle.
     */
    public double[] column(String channel) {
        Integer c = index.get(channel);
        double[] out = new double[rows.size()];
        if (c == null) {
            if (!has(channel)) {
                throw new IllegalArgumentException("the trace has no channel " + channel);
            }
            String[] bc = Channels.bodyChannel(channel);
            switch (bc[1]) {
                case "speed" -> {
                    double[] vx = column(Channels.body(bc[0], "vx"));
                    double[] vy = column(Channels.body(bc[0], "vy"));
                    for (int i = 0; i < out.length; i++) {
                        out[i] = Math.hypot(vx[i], vy[i]);
                    }
                }
                case "displacement" -> {
                    double[] x = column(Channels.body(bc[0], "x"));
                    double[] y = column(Channels.body(bc[0], "y"));
                    for (int i = 0; i < out.length; i++) {
                        out[i] = Math.hypot(x[i] - x[0], y[i] - y[0]);
                    }
                }
                default -> {
                    double[] a = column(Channels.body(bc[0], "angle"));
                    for (int i = 0; i < out.length; i++) {
                        out[i] = a[i] - a[0];
                    }
                }
            }
            return out;
        }
        for (int i = 0; i < out.length; i++) {
            out[i] = rows.get(i)[c];
        }
        return out;
    }
}
