package org.emini.bench.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.emini.bench.run.Measurement;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.VectorGraphicsEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.internal.chartpart.Chart;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** The report's plots, written with XChart as SVG (for the page) and PNG. */
public final class Charts {
    // One colour per engine of a full run (eight, with emini-2t), so that no two share one.
    private static final Color[] COLORS = {
        new Color(0xD62728), new Color(0x1F77B4), new Color(0x2CA02C), new Color(0xFF7F0E), new Color(0x9467BD),
        new Color(0x8C564B), new Color(0x17BECF), new Color(0xE377C2), new Color(0xBCBD22)};

    private Charts() {
    }

    /** How many engines the plots tell apart by colour. */
    public static int colourCount() {
        return COLORS.length;
    }

    /**
     * The scene plot's lowest tick: the power of ten at or below the fastest bar, so that every
     * measured bar shows and the stand-in for a missing one (1e-6) does not; 0.01 when no bar has a
     * positive finite time (a log axis cannot start at 0).
     */
    static double floor(double fastest) {
        return fastest > 0 && fastest < Double.POSITIVE_INFINITY ? Math.pow(10, Math.floor(Math.log10(fastest))) : 0.01;
    }

    /** Time per tick of every scene and engine, grouped by scene, log scale. Returns the file stem. */
    public static String sceneTimes(Path dir, List<BenchReport.SceneEntry> scenes, List<String> engines) throws IOException {
        CategoryChart c = new CategoryChartBuilder().width(1100).height(520)
            .title("Time per tick (CPU ms, log scale)").xAxisTitle("scene").yAxisTitle("ms per tick").build();
        c.getStyler().setYAxisLogarithmic(true);
        // Outside the plot: inside, it covered the first scene's bars.
        c.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        c.getStyler().setSeriesColors(COLORS);
        c.getStyler().setChartBackgroundColor(Color.WHITE);
        c.getStyler().setAvailableSpaceFill(0.8);
        c.getStyler().setXAxisLabelRotation(20);
        List<String> names = new ArrayList<>();
        for (BenchReport.SceneEntry s : scenes) {
            if ("ran".equals(s.status())) {
                names.add(s.id().replace("bench/", ""));
            }
        }
        if (names.isEmpty()) {
            return null;
        }
        double least = Double.POSITIVE_INFINITY;
        for (String engine : engines) {
            List<Double> ys = new ArrayList<>();
            for (BenchReport.SceneEntry s : scenes) {
                if (!"ran".equals(s.status())) {
                    continue;
                }
                Double y = null;
                for (Measurement m : s.results()) {
                    if (m.engine().equals(engine) && m.cost() != null) {
                        y = m.cost();
                        least = Math.min(least, y);
                    }
                }
                // XChart's log axis cannot draw a missing bar; a tiny value stands for "did not run".
                ys.add(y == null ? 1e-6 : y);
            }
            c.addSeries(engine, names, ys);
        }
        // A fixed 0.01 hid a sleeping scene's 0.005 ms bars.
        c.getStyler().setYAxisMin(floor(least));
        return save(c, dir, "scenes");
    }

    /** Time per tick against body count, log-log, one line per engine, with a linear guide. */
    public static String scaling(Path dir, List<Measurement> scaling, List<String> engines) throws IOException {
        XYChart c = new XYChartBuilder().width(900).height(560)
            .title("Rain: time per tick against bodies (log-log)").xAxisTitle("dynamic bodies").yAxisTitle("CPU ms per tick").build();
        c.getStyler().setXAxisLogarithmic(true);
        c.getStyler().setYAxisLogarithmic(true);
        c.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        c.getStyler().setChartBackgroundColor(Color.WHITE);
        int k = 0;
        double[] guide = null;
        for (String engine : engines) {
            List<Double> xs = new ArrayList<>();
            List<Double> ys = new ArrayList<>();
            for (Measurement m : scaling) {
                if (m.engine().equals(engine) && m.cost() != null) {
                    xs.add((double) m.dynamicBodies());
                    ys.add(m.cost());
                }
            }
            if (xs.isEmpty()) {
                k++;
                continue;
            }
            XYSeries s = c.addSeries(engine, xs, ys);
            s.setLineColor(COLORS[k % COLORS.length]);
            s.setMarkerColor(COLORS[k % COLORS.length]);
            s.setMarker(SeriesMarkers.CIRCLE);
            if (guide == null) {
                guide = new double[] {xs.get(0), ys.get(0), xs.get(xs.size() - 1)};
            }
            k++;
        }
        if (guide == null) {
            return null;
        }
        XYSeries g = c.addSeries("linear (slope 1) from " + engines.get(0) + "'s first point",
            new double[] {guide[0], guide[2]}, new double[] {guide[1], guide[1] * guide[2] / guide[0]});
        g.setLineColor(Color.GRAY);
        g.setLineStyle(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f));
        g.setMarker(SeriesMarkers.NONE);
        return save(c, dir, "scaling");
    }

    private static String save(Chart<?, ?> c, Path dir, String stem) throws IOException {
        BitmapEncoder.saveBitmap(c, dir.resolve(stem).toString(), BitmapEncoder.BitmapFormat.PNG);
        VectorGraphicsEncoder.saveVectorGraphic(c, dir.resolve(stem).toString(), VectorGraphicsEncoder.VectorGraphicsFormat.SVG);
        return stem;
    }
}
