package org.emini.harness.run;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.emini.dynamics.Body;
import org.emini.harness.build.BuiltWorld;
import org.emini.harness.build.UnsupportedElementException;
import org.emini.harness.metrics.Metric;
import org.emini.harness.metrics.Metrics;
import org.emini.harness.scenario.Channels;
import org.emini.harness.scenario.MetricSpec;
import org.emini.harness.scenario.Scenario;

/**
 * The expectations on a run's extremes ({@code of: max, min, maxAbs, maxDrift}, {@code staysInside} and a
 * {@code stable} bound on the energy's rise), judged on every tick when the scene records less often: a
 * joint that opens for one tick between two samples must not pass a bound on its largest error, nor a
 * body that leaves its region and comes back. Holds only the channels those expectations read, with
 * metric instances of its own (a metric's sample may keep state, such as the penetration per pair that
 * the report shows). The recorded trace, which the oracle comparison and the trace files use, is
 * untouched.
 */
final class EveryTick {
    private final Trace trace;
    private final Body[] bodies;
    private final List<Metric> metrics;

    private EveryTick(Trace trace, Body[] bodies, List<Metric> metrics) {
        this.trace = trace;
        this.bodies = bodies;
        this.metrics = metrics;
    }

    /**
     * The every-tick record of a scene, or null when there is nothing to add: the scene samples every tick,
     * or none of its expectations reads an extreme.
     *
     * @param every ticks between the scene's own samples
     * @throws UnsupportedElementException for a metric the engine cannot feed (as the scene's own would)
     */
    static EveryTick of(Scenario scenario, BuiltWorld built, long every) throws UnsupportedElementException {
        if (every <= 1) {
            return null;
        }
        Set<String> channels = new LinkedHashSet<>();
        scenario.run().expect().forEach(e -> channels.addAll(e.extremeChannels()));
        if (channels.isEmpty()) {
            return null;
        }
        Set<String> names = new LinkedHashSet<>();
        List<MetricSpec> specs = new ArrayList<>();
        for (String c : channels) {
            String[] bc = Channels.bodyChannel(c);
            if (bc == null) {
                for (MetricSpec m : scenario.run().record().metrics()) {
                    if (m.channels().contains(c) && !specs.contains(m)) {
                        specs.add(m);
                    }
                }
            } else if (Channels.isGroup(bc[0])) {
                // Every member, in the order the scene creates them (a group's verdict reads that order).
                built.bodies().keySet().stream().filter(n -> Channels.matches(bc[0], n)).forEach(names::add);
            } else {
                names.add(bc[0]);
            }
        }
        List<Metric> metrics = Metrics.create(specs, built);
        List<String> metricChannels = new ArrayList<>();
        metrics.forEach(m -> metricChannels.addAll(m.channels()));
        List<String> ordered = new ArrayList<>(built.bodies().keySet());
        ordered.retainAll(names);
        Body[] bodies = ordered.stream().map(built::body).toArray(Body[]::new);
        return new EveryTick(new Trace(scenario.world().timestep(), ordered, metricChannels), bodies, metrics);
    }

    /** After every tick (and once before the first): the metrics' monitors, then a sample. */
    void afterTick(long tick) {
        if (tick > 0) {
            for (Metric m : metrics) {
                m.afterTick();
            }
        }
        ScenarioRunner.sample(trace, tick, bodies, metrics);
    }

    /** The every-tick record. */
    Trace trace() {
        return trace;
    }
}
