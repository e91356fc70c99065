package org.emini.harness.expect;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.emini.harness.closedform.ClosedForm;
import org.emini.harness.run.Trace;
import org.emini.harness.scenario.Channels;
import org.emini.harness.scenario.ExpectationSpec;
import org.emini.harness.scenario.ReferenceTrace;

/**
 * Judges expectations on a trace. A figure that is NaN or infinite never passes.
 */
public final class Evaluator {
    private Evaluator() {
    }

    /**
     * Judges one expectation.
     *
     * @param e the expectation
     * @param trace the sampled run
     * @param closedForm the scene's closed form, or null
     */
    public static Verdict evaluate(ExpectationSpec e, Trace trace, ClosedForm closedForm) {
        if (e.group() != null) {
            return group(e, trace, closedForm);
        }
        int[] window = window(e, trace);
        if (window[0] > window[1]) {
            return verdict(e, false, Double.NaN, "no sample in the window [" + e.windowFrom() + ", " + e.windowUntil() + "] s");
        }
        switch (e.kind()) {
            case METRIC: {
                double[] v = trace.column(e.channel());
                if (e.minus() != null) {
                    double[] m = trace.column(e.minus());
                    for (int i = 0; i < v.length; i++) {
                        v[i] -= m[i];
                    }
                }
                ReferenceTrace ref = e.minusTrace();
                if (ref != null) {
                    String mismatch = ref.mismatch(trace.timestep(), ticks(trace));
                    if (mismatch != null) {
                        return verdict(e, false, Double.NaN, mismatch);
                    }
                    for (int i = 0; i < v.length; i++) {
                        v[i] -= ref.values()[i];
                    }
                }
                double x = reduce(e, v, trace, window);
                if (e.relativeTo() == null) {
                    Verdict b = bounded(e, x);
                    return ref == null ? b : verdict(e, b.passed(), x, b.detail() + " (this run's " + e.channel()
                            + " minus " + ref.channel() + " of the reference trace " + ref.file() + ")");
                }
                ExpectationSpec f = e.relativeTo();
                int[] fw = window(f, trace);
                double r = fw[0] <= fw[1] ? reduce(f, trace.column(f.channel()), trace, fw) : Double.NaN;
                Verdict v2 = bounded(e.timesBounds(r), x);
                return verdict(e, v2.passed() && Double.isFinite(r), x, v2.detail() + " (the bounds times " + f.channel()
                        + " " + (f.of() != null ? f.of() : "at " + fmt(f.at()) + " s") + " = " + fmt(r) + ")");
            }
            case CLOSED_FORM:
                return bounded(e, closedFormError(e, trace, closedForm, window));
            case ENDS_NEAR: {
                double x = trace.column(Channels.body(e.body(), "x"))[window[1]];
                double y = trace.column(Channels.body(e.body(), "y"))[window[1]];
                double d = Math.hypot(x - e.point()[0], y - e.point()[1]);
                return verdict(e, d <= e.tolerance(), d, String.format(Locale.ROOT,
                        "ends at (%s, %s), %s px from the target (tolerance %s)", fmt(x), fmt(y), fmt(d), fmt(e.tolerance())));
            }
            case STAYS_INSIDE: {
                double[] xs = trace.column(Channels.body(e.body(), "x"));
                double[] ys = trace.column(Channels.body(e.body(), "y"));
                double worst = 0;
                for (int i = window[0]; i <= window[1]; i++) {
                    double out = Math.max(Math.max(e.point()[0] - xs[i], xs[i] - e.max()[0]),
                            Math.max(e.point()[1] - ys[i], ys[i] - e.max()[1]));
                    worst = Double.isNaN(out) ? Double.NaN : Math.max(worst, out);
                }
                return verdict(e, worst <= 0, worst, worst > 0 || Double.isNaN(worst)
                        ? "left the region by " + fmt(worst) + " px" : "stayed inside");
            }
            case NO_TUNNELLING: {
                double count = trace.column("tunnelling.count")[window[1]];
                return verdict(e, count == 0, count, fmt(count) + " wall crossings");
            }
            default:
                return stable(e, trace, window);
        }
    }

    /**
     * A group ({@code box[*]}): the expectation on every member, in the trace's order (the order the scene
     * creates them). It holds when it holds for each; the figure is the first failing member's, else the one
     * nearest its bound. With {@code inOrder}, the members' first crossings must also come one after another.
     */
    private static Verdict group(ExpectationSpec e, Trace trace, ClosedForm closedForm) {
        List<String> members = new ArrayList<>();
        for (String b : trace.bodies()) {
            if (Channels.matches(e.group(), b)) {
                members.add(b);
            }
        }
        if (members.isEmpty()) {
            return verdict(e, false, Double.NaN, "no recorded body matches " + e.group());
        }
        Verdict worst = null;
        double margin = Double.POSITIVE_INFINITY;
        String worstBody = null;
        int failed = 0;
        double[] times = new double[members.size()];
        for (int i = 0; i < members.size(); i++) {
            ExpectationSpec one = e.forBody(members.get(i));
            boolean bounded = !Double.isNaN(e.atMost()) || !Double.isNaN(e.atLeast()) || !Double.isNaN(e.near());
            Verdict v = bounded || one.kind() != ExpectationSpec.Kind.METRIC ? evaluate(one, trace, closedForm) : null;
            if (one.kind() == ExpectationSpec.Kind.METRIC && one.of() != null) {
                int[] w = window(one, trace);
                times[i] = w[0] <= w[1] ? reduce(one, trace.column(one.channel()), trace, w) : Double.NaN;
            }
            if (v == null) {
                continue;
            }
            double m = margin(e, v.measured());
            if (!v.passed()) {
                failed++;
            }
            if (worst == null || (!v.passed() && worst.passed()) || (v.passed() == worst.passed() && m < margin)) {
                worst = v;
                margin = m;
                worstBody = members.get(i);
            }
        }
        if (e.inOrder()) {
            for (int i = 1; i < times.length; i++) {
                if (!(times[i] > times[i - 1])) {
                    return verdict(e, false, times[i], String.format(Locale.ROOT, "%s crosses at %s s, not after %s at %s s "
                            + "(%d bodies in order of creation)", members.get(i), fmt(times[i]), members.get(i - 1),
                            fmt(times[i - 1]), members.size()));
                }
            }
            if (worst == null) {
                return verdict(e, true, times[times.length - 1], members.size() + " bodies cross in order, from "
                        + fmt(times[0]) + " s to " + fmt(times[times.length - 1]) + " s");
            }
        }
        String detail = worstBody + ": " + worst.detail() + (failed > 0 ? " (" + failed + " of " + members.size()
                + " bodies fail)" : " (the nearest to its bound of " + members.size() + " bodies)");
        return verdict(e, failed == 0, worst.measured(), detail);
    }

    /** How far inside its bound a figure is (negative outside); NaN counts as outside. */
    private static double margin(ExpectationSpec e, double x) {
        double m = Double.POSITIVE_INFINITY;
        if (!Double.isNaN(e.atMost())) {
            m = Math.min(m, e.atMost() - x);
        }
        if (!Double.isNaN(e.atLeast())) {
            m = Math.min(m, x - e.atLeast());
        }
        if (!Double.isNaN(e.near())) {
            m = Math.min(m, e.tolerance() - Math.abs(x - e.near()));
        }
        return Double.isNaN(m) ? Double.NEGATIVE_INFINITY : m;
    }

    private static Verdict stable(ExpectationSpec e, Trace trace, int[] w) {
        double nonFinite = max(trace.column("stability.nonFinite"), w);
        if (nonFinite != 0) {
            return verdict(e, false, nonFinite, "NaN or infinite state in " + fmt(nonFinite) + " bodies");
        }
        double speed = max(trace.column("stability.maxSpeed"), w);
        if (!Double.isNaN(e.maxSpeed()) && !(speed <= e.maxSpeed())) {
            return verdict(e, false, speed, "speed reached " + fmt(speed) + " px/s > " + fmt(e.maxSpeed()));
        }
        double spin = max(trace.column("stability.maxAngularSpeed"), w);
        if (!Double.isNaN(e.maxAngularSpeed()) && !(spin <= e.maxAngularSpeed())) {
            return verdict(e, false, spin, "angular speed reached " + fmt(spin) + " rad/s > " + fmt(e.maxAngularSpeed()));
        }
        if (!Double.isNaN(e.maxEnergyRise())) {
            double[] energy = trace.column("energy.total");
            double rise = max(energy, w) - energy[w[0]];
            if (!(rise <= e.maxEnergyRise())) {
                return verdict(e, false, rise, "total energy rose by " + fmt(rise) + " > " + fmt(e.maxEnergyRise()));
            }
        }
        return verdict(e, true, speed, "finite; max speed " + fmt(speed) + " px/s, max |ω| " + fmt(spin) + " rad/s");
    }

    private static double reduce(ExpectationSpec e, double[] v, Trace trace, int[] w) {
        if (e.of() == null) {
            return v[nearest(trace, e.at())];
        }
        double initial = v[w[0]];
        double scale = e.relative() ? Math.abs(initial) : 1;
        switch (e.of()) {
            case "final": return v[w[1]];
            case "initial": return initial;
            case "max": return max(v, w);
            case "min": {
                double m = Double.POSITIVE_INFINITY;
                for (int i = w[0]; i <= w[1]; i++) {
                    m = Double.isNaN(v[i]) ? Double.NaN : Math.min(m, v[i]);
                }
                return m;
            }
            case "mean": {
                double s = 0;
                for (int i = w[0]; i <= w[1]; i++) {
                    s += v[i];
                }
                return s / (w[1] - w[0] + 1);
            }
            case "maxAbs": {
                double m = 0;
                for (int i = w[0]; i <= w[1]; i++) {
                    m = Double.isNaN(v[i]) ? Double.NaN : Math.max(m, Math.abs(v[i]));
                }
                return m;
            }
            case "drift": return (v[w[1]] - initial) / scale;
            case "firstCrossing": return firstCrossing(v, trace, w, e.crossing());
            case "period": return period(v, trace, w, e.crossing());
            case "maxDrift": {
                double m = 0;
                for (int i = w[0]; i <= w[1]; i++) {
                    m = Double.isNaN(v[i]) ? Double.NaN : Math.max(m, Math.abs(v[i] - initial));
                }
                return m / scale;
            }
            default:
                throw new IllegalArgumentException("unknown reduction " + e.of());
        }
    }

    /**
     * The time (s) the series first reaches {@code value} from the side it starts on, interpolated linearly
     * between the two samples around it; NaN when it never does in the window.
     */
    static double firstCrossing(double[] v, Trace trace, int[] w, double value) {
        double side = Math.signum(v[w[0]] - value);
        if (side == 0) {
            return trace.time(w[0]);
        }
        for (int i = w[0] + 1; i <= w[1]; i++) {
            if (Double.isNaN(v[i])) {
                return Double.NaN;
            }
            if (Math.signum(v[i] - value) != side) {
                double f = (value - v[i - 1]) / (v[i] - v[i - 1]);
                return trace.time(i - 1) + f * (trace.time(i) - trace.time(i - 1));
            }
        }
        return Double.NaN;
    }

    /**
     * The mean time (s) between successive upward crossings of {@code value} (the window's mean when NaN),
     * each interpolated linearly: an oscillation's period. NaN with fewer than two crossings.
     */
    static double period(double[] v, Trace trace, int[] w, double value) {
        double level = value;
        if (Double.isNaN(level)) {
            level = 0;
            for (int i = w[0]; i <= w[1]; i++) {
                level += v[i] / (w[1] - w[0] + 1);
            }
        }
        double first = Double.NaN;
        double last = Double.NaN;
        int n = 0;
        for (int i = w[0] + 1; i <= w[1]; i++) {
            if (v[i - 1] < level && v[i] >= level) {
                double t = trace.time(i - 1) + (level - v[i - 1]) / (v[i] - v[i - 1]) * (trace.time(i) - trace.time(i - 1));
                if (n == 0) {
                    first = t;
                }
                last = t;
                n++;
            }
        }
        return n < 2 ? Double.NaN : (last - first) / (n - 1);
    }

    private static double closedFormError(ExpectationSpec e, Trace trace, ClosedForm model, int[] w) {
        if (model == null) {
            return Double.NaN;
        }
        double[] v = trace.column(e.channel());
        double max = 0;
        double sumSq = 0;
        int n = 0;
        double last = Double.NaN;
        int from = w[0];
        int until = w[1];
        if (e.of() == null) {
            from = until = nearest(trace, e.at());
        }
        for (int i = from; i <= until; i++) {
            double predicted = model.predict(e.channel(), trace.time(i));
            if (Double.isNaN(predicted)) {
                continue;
            }
            double err = Math.abs(v[i] - predicted);
            if (Double.isNaN(err)) {
                return Double.NaN;
            }
            max = Math.max(max, err);
            sumSq += err * err;
            n++;
            last = err;
        }
        if (n == 0) {
            return Double.NaN;
        }
        if (e.of() == null || e.of().equals("finalError")) {
            return last;
        }
        return e.of().equals("rmsError") ? Math.sqrt(sumSq / n) : max;
    }

    private static Verdict bounded(ExpectationSpec e, double x) {
        boolean ok = Double.isFinite(x);
        StringBuilder bound = new StringBuilder();
        if (!Double.isNaN(e.atMost())) {
            ok &= x <= e.atMost();
            bound.append(" ≤ ").append(fmt(e.atMost()));
        }
        if (!Double.isNaN(e.atLeast())) {
            ok &= x >= e.atLeast();
            bound.append(" ≥ ").append(fmt(e.atLeast()));
        }
        if (!Double.isNaN(e.near())) {
            ok &= Math.abs(x - e.near()) <= e.tolerance();
            bound.append(" within ").append(fmt(e.tolerance())).append(" of ").append(fmt(e.near()));
        }
        return verdict(e, ok, x, "measured " + fmt(x) + ", expected" + bound);
    }

    private static double max(double[] v, int[] w) {
        double m = Double.NEGATIVE_INFINITY;
        for (int i = w[0]; i <= w[1]; i++) {
            m = Double.isNaN(v[i]) ? Double.NaN : Math.max(m, v[i]);
        }
        return m;
    }

    private static long[] ticks(Trace trace) {
        long[] out = new long[trace.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = trace.tick(i);
        }
        return out;
    }

    private static int nearest(Trace trace, double t) {
        int best = 0;
        for (int i = 1; i < trace.size(); i++) {
            if (Math.abs(trace.time(i) - t) < Math.abs(trace.time(best) - t)) {
                best = i;
            }
        }
        return best;
    }

    /** Indices of the first and last samples inside the expectation's window (first &gt; last if none). */
    private static int[] window(ExpectationSpec e, Trace trace) {
        int first = -1;
        int last = -2;
        double eps = trace.timestep() * 1e-6;
        for (int i = 0; i < trace.size(); i++) {
            double t = trace.time(i);
            if (t >= e.windowFrom() - eps && t <= e.windowUntil() + eps) {
                if (first < 0) {
                    first = i;
                }
                last = i;
            }
        }
        return first < 0 ? new int[] {0, -1} : new int[] {first, last};
    }

    private static Verdict verdict(ExpectationSpec e, boolean ok, double measured, String detail) {
        return new Verdict(e.describe(), ok && !Double.isNaN(measured), measured, detail, e.knownFailure());
    }

    /** Formats a figure with 4 significant digits. */
    public static String fmt(double v) {
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            return Double.toString(v);
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e9) {
            return Long.toString((long) v);
        }
        return String.format(Locale.ROOT, "%.4g", v);
    }
}
