package org.emini.harness.load;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.List;
import org.emini.harness.scenario.ActionSpec;
import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Channels;
import org.emini.harness.scenario.ExpectationSpec;
import org.emini.harness.scenario.RecordSpec;
import org.emini.harness.scenario.Scenario;
import org.emini.harness.scenario.Section;

/**
 * The run-size limits a schema cannot state, because they are products or totals over the scene
 * ({@link Limits}): ticks, bodies × ticks, the trace's size, the particle pools. A scene over one of
 * them is refused where it is written, before anything is built or allocated.
 */
final class Budget {
    private Budget() {
    }

    /** A limit the scene passes, and where to look. */
    record Excess(JsonPath path, String message) {
    }

    static List<Excess> check(Scenario s) {
        List<Excess> out = new ArrayList<>();
        JsonPath duration = JsonPath.ROOT.key("run").key("duration");
        double h = s.world().timestep();
        double ticks = Math.ceil(s.run().duration() / h - 1e-9);
        if (ticks > Limits.TICKS) {
            out.add(new Excess(duration, String.format("%s s at %s s a tick is %.4g ticks, more than the %d a run may have",
                    s.run().duration(), h, ticks, Limits.TICKS)));
            return out;
        }
        if (ticks * s.bodies().size() > Limits.BODY_TICKS) {
            out.add(new Excess(duration, String.format("%d bodies × %.0f ticks is more than the %d body-ticks a run may "
                    + "have", s.bodies().size(), ticks, Limits.BODY_TICKS)));
        }
        RecordSpec record = s.run().record();
        double samples = Math.floor(ticks / record.samplingTicks(h)) + 2;
        double values = samples * (6.0 * recorded(s) + 3.0 * record.metrics().size());
        if (values > Limits.TRACE_VALUES) {
            out.add(new Excess(JsonPath.ROOT.key("run").key("record"), String.format("the trace would hold about %.3g "
                    + "values (%.0f samples × 6 per recorded body and 3 per metric), more than the %d a run may keep; "
                    + "record fewer bodies or sample less often (every)", values, samples, Limits.TRACE_VALUES)));
        }
        if (record.samplingTicks(h) > 1) {
            // Expectations on extremes are judged on every tick (run/EveryTick): their bodies and metrics too.
            double every = (ticks + 1) * (6.0 * judgedEveryTick(s) + 3.0 * record.metrics().size());
            if (every > Limits.TRACE_VALUES) {
                out.add(new Excess(JsonPath.ROOT.key("run").key("expect"), String.format("the expectations on extremes "
                        + "(max, min, maxAbs, maxDrift, staysInside, an energy rise) are judged on every tick: about %.3g "
                        + "values (%.0f ticks), more than the %d a run may keep; bound the extremes of fewer bodies",
                        every, ticks + 1, Limits.TRACE_VALUES)));
            }
        }
        Section particles = s.elements().get("particles");
        if (particles != null) {
            long pool = 0;
            for (JsonNode e : particles.node()) {
                pool += e.path("maxCount").asLong(100);
            }
            if (pool > Limits.PARTICLES) {
                out.add(new Excess(particles.path(), "the emitters' pools hold " + pool + " particles together, more "
                        + "than the " + Limits.PARTICLES + " a scene may have"));
            }
        }
        for (ActionSpec a : s.actions()) {
            if (Math.ceil(a.at() / h - 1e-9) >= ticks) {
                out.add(new Excess(a.path().key("at"), "at " + a.at() + " s the run (" + s.run().duration()
                        + " s) is over: the action would never happen"));
            }
        }
        return out;
    }

    /** Bodies whose extremes the expectations read ({@link ExpectationSpec#extremeChannels()}), a group by its members. */
    private static int judgedEveryTick(Scenario s) {
        int n = 0;
        for (ExpectationSpec e : s.run().expect()) {
            for (String c : e.extremeChannels()) {
                String[] bc = Channels.bodyChannel(c);
                if (bc == null) {
                    continue;
                }
                n += Channels.isGroup(bc[0]) ? (int) s.bodies().stream().filter(b -> Channels.matches(bc[0], b.name())).count() : 1;
            }
        }
        return n;
    }

    private static int recorded(Scenario s) {
        RecordSpec r = s.run().record();
        int expectations = s.run().expect().size();
        if (r.bodies() == null) {
            return r.bodyNames().size() + expectations;
        }
        return switch (r.bodies()) {
            case "all" -> s.bodies().size();
            case "dynamic" -> (int) s.bodies().stream().map(BodySpec::state).filter(b -> !b.isStatic()).count()
                    + expectations;
            default -> expectations;
        };
    }
}
