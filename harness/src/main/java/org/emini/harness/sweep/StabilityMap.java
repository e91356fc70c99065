package org.emini.harness.sweep;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.emini.harness.run.Trace;
import org.emini.harness.scenario.Channels;

/**
 * Runs a stability family over the grid's timesteps in each backend and judges every cell.
 */
public final class StabilityMap {
    /**
     * One cell of a map.
     *
     * @param value the parameter value
     * @param rate ticks per second
     * @param verdict {@code stable}, {@code NaN}, {@code energy growth}, {@code energy error} (a bounded rise), {@code tunnelling},
     *     {@code penetration}, {@code collapse}, {@code unsupported} or {@code error}
     * @param detail the measured figure
     */
    public record Cell(double value, int rate, String verdict, String detail) {
    }

    /**
     * A family's map for one backend.
     *
     * @param family the family
     * @param engine the backend ({@code emini}, {@code pymunk})
     * @param note why there are no cells (the backend is unavailable), or ""
     * @param cells one per value and rate
     */
    public record Map(String family, String engine, String note, List<Cell> cells) {
    }

    private StabilityMap() {
    }

    /** Runs one family in one backend over the rates. */
    public static Map run(StabilityFamily family, SweepBackend backend, List<Integer> rates, int iterations) {
        List<Cell> cells = new ArrayList<>();
        if (backend.unavailable() != null) {
            return new Map(family.name(), backend.name(), backend.unavailable(), cells);
        }
        for (double v : family.values()) {
            String text = family.scene().apply(v);
            for (int rate : rates) {
                String id = "stability/" + family.name() + "-" + v;
                String variant = SceneVariant.rewrite(text, id, 1.0 / rate, iterations, 1.0 / rates.get(0));
                SweepBackend.Measured m = backend.run(id, variant, 0); // the trace only: no timing
                cells.add(m.status().equals("ok") ? judge(family, v, rate, m.trace())
                        : new Cell(v, rate, m.status(), m.message()));
            }
        }
        return new Map(family.name(), backend.name(), "", cells);
    }

    static Cell judge(StabilityFamily f, double v, int rate, Trace t) {
        for (String b : t.bodies()) {
            double[] x = t.column(Channels.body(b, "x"));
            double[] y = t.column(Channels.body(b, "y"));
            for (int i = 0; i < x.length; i++) {
                if (!Double.isFinite(x[i]) || !Double.isFinite(y[i])) {
                    return new Cell(v, rate, "NaN", "non-finite state of " + b + " at " + fmt(t.time(i)) + " s");
                }
            }
        }
        if (t.has("stability.nonFinite") && Accuracy.maxAbs(t.column("stability.nonFinite")) > 0) {
            return new Cell(v, rate, "NaN", "non-finite state");
        }
        if (t.has("tunnelling.count")) {
            double[] c = t.column("tunnelling.count");
            if (c[c.length - 1] > 0) {
                return new Cell(v, rate, "tunnelling", fmt(c[c.length - 1]) + " crossings");
            }
        }
        if (t.has("energy.total")) {
            double[] e = t.column("energy.total");
            double scale = Math.max(1, Math.max(Math.abs(e[0]), Accuracy.maxAbs(t.column("energy.kinetic"))));
            double rise = 0;
            for (double x : e) {
                rise = Math.max(rise, x - e[0]);
            }
            if (rise > 0.01 * scale) {
                // Growth is unstable; a bounded oscillation or a one-off kick is an error of the
                // energy, not a blow-up: tell them apart by the peak of the last third of the run
                // against the first third's.
                int third = Math.max(1, e.length / 3);
                double early = Double.NEGATIVE_INFINITY;
                double late = Double.NEGATIVE_INFINITY;
                for (int i = 0; i < e.length; i++) {
                    if (i < third) {
                        early = Math.max(early, e[i]);
                    } else if (i >= e.length - third) {
                        late = Math.max(late, e[i]);
                    }
                }
                String detail = "total energy rose by " + fmt(rise) + " (" + fmt(100 * rise / scale) + "%)";
                if (late - early > 0.01 * scale) {
                    return new Cell(v, rate, "energy growth", detail + ", still growing: the last third's peak is "
                        + fmt(100 * (late - early) / scale) + "% above the first third's");
                }
                return new Cell(v, rate, "energy error", detail + ", bounded: the last third's peak is not above the first third's");
            }
        }
        if (t.has("penetration.max")) {
            double p = Accuracy.maxAbs(t.column("penetration.max"));
            double bound = f.penetrationBound().apply(v);
            if (p > bound) {
                return new Cell(v, rate, "penetration", "overlap " + fmt(p) + " px > " + fmt(bound));
            }
        }
        if (!Double.isNaN(f.moveBound())) {
            double worst = 0;
            for (String b : t.bodies()) {
                double[] x = t.column(Channels.body(b, "x"));
                double[] y = t.column(Channels.body(b, "y"));
                for (int i = 0; i < x.length; i++) {
                    worst = Math.max(worst, Math.hypot(x[i] - x[0], y[i] - y[0]));
                }
            }
            if (worst > f.moveBound()) {
                return new Cell(v, rate, "collapse", "a body moved " + fmt(worst) + " px > " + fmt(f.moveBound()));
            }
        }
        return new Cell(v, rate, "stable", "");
    }

    static String fmt(double v) {
        return String.format(Locale.ROOT, "%.3g", v);
    }
}
