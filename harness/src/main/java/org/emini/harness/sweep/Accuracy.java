package org.emini.harness.sweep;

import java.util.ArrayList;
import java.util.List;
import org.emini.harness.closedform.ClosedForm;
import org.emini.harness.run.Trace;
import org.emini.harness.scenario.Channels;

/**
 * Error of a run against a reference, per sample: the mean distance (px) of the compared bodies from
 * where the reference puts them (Erez, Tassa and Todorov's "mean deviation of body positions"). The
 * reference is a closed form (only the bodies and samples it predicts count) or another trace of the
 * same scene (its positions interpolated linearly in time).
 */
public final class Accuracy {
    private Accuracy() {
    }

    /**
     * Final-time, whole-run (max) and RMS error.
     *
     * @param errors the per-sample errors, in time order
     * @return {final, max, rms}; NaN when there are none or one is NaN (the run blew up)
     */
    public static double[] reduce(double[] errors) {
        if (errors.length == 0) {
            return new double[] {Double.NaN, Double.NaN, Double.NaN};
        }
        double max = 0;
        double sq = 0;
        for (double e : errors) {
            if (Double.isNaN(e)) {
                return new double[] {Double.NaN, Double.NaN, Double.NaN};
            }
            max = Math.max(max, e);
            sq += e * e;
        }
        return new double[] {errors[errors.length - 1], max, Math.sqrt(sq / errors.length)};
    }

    /** Per-sample error against a closed form, over the samples where it predicts a compared body's x or y. */
    public static double[] againstClosedForm(Trace run, List<String> bodies, ClosedForm model) {
        List<Double> out = new ArrayList<>();
        for (int i = 0; i < run.size(); i++) {
            double t = run.time(i);
            double sum = 0;
            int n = 0;
            for (String b : bodies) {
                double px = model.predict(Channels.body(b, "x"), t);
                double py = model.predict(Channels.body(b, "y"), t);
                if (Double.isNaN(px) && Double.isNaN(py)) {
                    continue;
                }
                double dx = Double.isNaN(px) ? 0 : run.column(Channels.body(b, "x"))[i] - px;
                double dy = Double.isNaN(py) ? 0 : run.column(Channels.body(b, "y"))[i] - py;
                sum += Math.hypot(dx, dy);
                n++;
            }
            if (n > 0) {
                out.add(sum / n);
            }
        }
        return out.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /** Whether a closed form predicts anything of these bodies on this trace. */
    public static boolean predictsAny(Trace run, List<String> bodies, ClosedForm model) {
        return model != null && againstClosedForm(run, bodies, model).length > 0;
    }

    /** Per-sample error against a reference trace of the same scene. */
    public static double[] againstTrace(Trace run, List<String> bodies, Trace ref) {
        double[] out = new double[run.size()];
        for (int i = 0; i < run.size(); i++) {
            double t = run.time(i);
            double sum = 0;
            int n = 0;
            for (String b : bodies) {
                if (!ref.has(Channels.body(b, "x"))) {
                    continue;
                }
                double rx = at(ref, ref.column(Channels.body(b, "x")), t);
                double ry = at(ref, ref.column(Channels.body(b, "y")), t);
                sum += Math.hypot(run.column(Channels.body(b, "x"))[i] - rx, run.column(Channels.body(b, "y"))[i] - ry);
                n++;
            }
            out[i] = n == 0 ? 0 : sum / n;
        }
        return out;
    }

    /**
     * How far the reference moves the compared bodies: the largest distance (px) of a body from where it
     * starts, over the samples of {@code trace}. With a closed form, its predicted positions (a
     * coordinate it does not predict is taken from the trace); without, the trace's own (the reference
     * trace of a self-consistency error).
     */
    public static double motion(Trace trace, List<String> bodies, ClosedForm model) {
        double worst = 0;
        for (String b : bodies) {
            if (!trace.has(Channels.body(b, "x"))) {
                continue;
            }
            double[] x = trace.column(Channels.body(b, "x"));
            double[] y = trace.column(Channels.body(b, "y"));
            double x0 = Double.NaN;
            double y0 = Double.NaN;
            for (int i = 0; i < trace.size(); i++) {
                double t = trace.time(i);
                double px = model == null ? Double.NaN : model.predict(Channels.body(b, "x"), t);
                double py = model == null ? Double.NaN : model.predict(Channels.body(b, "y"), t);
                px = Double.isNaN(px) ? x[i] : px;
                py = Double.isNaN(py) ? y[i] : py;
                if (i == 0) {
                    x0 = px;
                    y0 = py;
                }
                double d = Math.hypot(px - x0, py - y0);
                if (Double.isFinite(d)) {
                    worst = Math.max(worst, d);
                }
            }
        }
        return worst;
    }

    /** A column's value at time t, linear between samples, held at the ends. */
    static double at(Trace trace, double[] column, double t) {
        int n = trace.size();
        if (t <= trace.time(0)) {
            return column[0];
        }
        for (int i = 1; i < n; i++) {
            double t1 = trace.time(i);
            if (Math.abs(t - t1) <= 1e-12) {
                return column[i]; // on a sample: its value exactly (a trace against itself errs by 0)
            }
            if (t < t1) {
                double t0 = trace.time(i - 1);
                double u = t1 == t0 ? 1 : (t - t0) / (t1 - t0);
                return column[i - 1] + u * (column[i] - column[i - 1]);
            }
        }
        return column[n - 1];
    }

    /**
     * Largest drift of a conserved quantity from its first value, over a scale.
     *
     * @return max |v(t) − v(0)| / scale (NaN if a value is)
     */
    public static double drift(double[] v, double scale) {
        double m = 0;
        for (double x : v) {
            if (Double.isNaN(x)) {
                return Double.NaN;
            }
            m = Math.max(m, Math.abs(x - v[0]));
        }
        return m / (scale > 0 ? scale : 1);
    }

    /** Largest absolute value of a column. */
    public static double maxAbs(double[] v) {
        double m = 0;
        for (double x : v) {
            m = Math.max(m, Math.abs(x));
        }
        return m;
    }
}
