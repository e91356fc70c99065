package org.emini.harness.sweep;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.ToDoubleFunction;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.VectorGraphicsEncoder;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Log-log work-precision plots drawn with XChart as SVG: per scene, error over the whole run against
 * cost, error at the final time against cost and, where the scene conserves energy or momentum, their
 * drift against cost; one line per engine and iteration count, its points the timesteps (Emini solid
 * with circles, pymunk dashed with diamonds, one colour per iteration count). Lower left is better. Points that are zero, NaN or unstable cannot be drawn on log axes and are left out.
 */
public final class WorkPrecisionPlots {
    private WorkPrecisionPlots() {
    }

    /** The file name stem of a scene's plots. */
    public static String stem(String scene) {
        return scene.replace('/', '_');
    }

    /**
     * Writes every plot the points allow.
     *
     * @return the number of files written
     */
    public static int write(List<SweepPoint> points, Path dir) throws IOException {
        return write(points, dir, false);
    }

    /**
     * Writes every plot the points allow, the cost axis in wall time or in CPU time.
     *
     * @param cpu whether the cost axis is {@code cpuCostSeconds} (else {@code costSeconds})
     * @return the number of files written
     */
    public static int write(List<SweepPoint> points, Path dir, boolean cpu) throws IOException {
        ToDoubleFunction<SweepPoint> cost = cpu ? SweepPoint::cpuCostSeconds : SweepPoint::costSeconds;
        String costTitle = "cost: " + (cpu ? "CPU" : "wall") + " seconds of the ticks per simulated second";
        System.setProperty("java.awt.headless", "true");
        Files.createDirectories(dir);
        Map<String, List<SweepPoint>> byScene = new TreeMap<>();
        for (SweepPoint p : points) {
            byScene.computeIfAbsent(p.scene(), s -> new ArrayList<>()).add(p);
        }
        int n = 0;
        for (Map.Entry<String, List<SweepPoint>> e : byScene.entrySet()) {
            String ref = e.getValue().stream().map(SweepPoint::reference).filter(r -> !r.isEmpty()).findFirst().orElse("");
            String against = ref.startsWith("closedForm:") ? "closed form " + ref.substring(11) : "tightest setting " + ref.replace("self:", "");
            // Short titles (the scene and the figure): XChart centres a title over the plot area, beside the
            // legend, and clips what does not fit; the reference goes on the y axis.
            n += plot(e.getValue(), SweepPoint::maxError, e.getKey() + ": whole-run error",
                    "max error (px) vs " + against, dir.resolve(stem(e.getKey()) + "-error"), cost, costTitle);
            n += plot(e.getValue(), SweepPoint::finalError, e.getKey() + ": final-time error",
                    "final error (px) vs " + against, dir.resolve(stem(e.getKey()) + "-final"), cost, costTitle);
            n += plot(e.getValue(), SweepPoint::energyDrift, e.getKey() + ": energy drift",
                    "max |E - E0| / max KE", dir.resolve(stem(e.getKey()) + "-energy"), cost, costTitle);
            n += plot(e.getValue(), SweepPoint::momentumDrift, e.getKey() + ": momentum drift",
                    "max |p - p0| / max |p|", dir.resolve(stem(e.getKey()) + "-momentum"), cost, costTitle);
        }
        return n;
    }

    /** Colours by iteration count (the same setting has the same colour in both engines). */
    private static final java.awt.Color[] COLOURS = {new java.awt.Color(0x1f77b4), new java.awt.Color(0xff7f0e),
        new java.awt.Color(0x2ca02c), new java.awt.Color(0xd62728), new java.awt.Color(0x9467bd),
        new java.awt.Color(0x8c564b), new java.awt.Color(0xe377c2), new java.awt.Color(0x7f7f7f)};

    /**
     * The lines of a plot: one per engine and iteration count ("emini, 10 iterations"), its points the
     * drawable ones (status ok, a positive finite figure and cost), ordered by rate.
     */
    static Map<String, List<SweepPoint>> lines(List<SweepPoint> points, ToDoubleFunction<SweepPoint> y) {
        return lines(points, y, SweepPoint::costSeconds);
    }

    static Map<String, List<SweepPoint>> lines(List<SweepPoint> points, ToDoubleFunction<SweepPoint> y,
                                               ToDoubleFunction<SweepPoint> cost) {
        Map<String, List<SweepPoint>> lines = new TreeMap<>();
        for (SweepPoint p : points) {
            double v = y.applyAsDouble(p);
            double c = cost.applyAsDouble(p);
            if (p.status().equals("ok") && v > 0 && Double.isFinite(v) && c > 0 && Double.isFinite(c)) {
                lines.computeIfAbsent(label(p), k -> new ArrayList<>()).add(p);
            }
        }
        lines.values().forEach(ps -> ps.sort(Comparator.comparingInt(SweepPoint::rate)));
        return lines;
    }

    /** A line's name: the engine and the iteration count. */
    static String label(SweepPoint p) {
        return String.format("%s, %2d iterations", p.engine(), p.iterations());
    }

    private static int plot(List<SweepPoint> points, ToDoubleFunction<SweepPoint> y, String title, String yTitle,
                            Path stem, ToDoubleFunction<SweepPoint> cost, String costTitle) throws IOException {
        Map<String, List<SweepPoint>> lines = lines(points, y, cost);
        if (lines.isEmpty()) {
            Files.deleteIfExists(stem.resolveSibling(stem.getFileName() + ".svg"));
            return 0;
        }
        List<Integer> iterations = points.stream().map(SweepPoint::iterations).distinct().sorted().toList();
        XYChart chart = new XYChartBuilder().width(800).height(440).title(title)
                .xAxisTitle(costTitle).yAxisTitle(yTitle).build();
        chart.getStyler().setChartTitleFont(new java.awt.Font(java.awt.Font.SANS_SERIF, java.awt.Font.BOLD, 12));
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setChartBackgroundColor(java.awt.Color.WHITE);
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideE);
        chart.getStyler().setLegendLayout(org.knowm.xchart.style.Styler.LegendLayout.Vertical);
        for (Map.Entry<String, List<SweepPoint>> line : lines.entrySet()) {
            List<SweepPoint> ps = line.getValue();
            double[] xs = ps.stream().mapToDouble(cost).toArray();
            double[] ys = ps.stream().mapToDouble(y).toArray();
            var s = chart.addSeries(line.getKey(), xs, ys);
            String engine = ps.get(0).engine();
            boolean oracle = !engine.startsWith("emini");
            // Emini circles (its double flavour, emini-double, squares), pymunk diamonds dashed, Box2D
            // triangles dotted: one colour per iteration count.
            s.setMarker(!oracle ? (engine.equals("emini") ? SeriesMarkers.CIRCLE : SeriesMarkers.SQUARE)
                    : engine.equals("box2d") ? SeriesMarkers.TRIANGLE_UP : SeriesMarkers.DIAMOND);
            java.awt.Color c = COLOURS[iterations.indexOf(ps.get(0).iterations()) % COLOURS.length];
            s.setLineColor(c);
            s.setMarkerColor(c);
            if (oracle) {
                // The oracle's lines dashed: the same colour is the same iteration count.
                float[] dashes = engine.equals("box2d") ? new float[] {2f, 3f} : new float[] {6f, 4f}; // flavour: float (AWT's)
                s.setLineStyle(new java.awt.BasicStroke(1.6f, java.awt.BasicStroke.CAP_BUTT, // flavour: float (AWT's)
                        java.awt.BasicStroke.JOIN_MITER, 10f, dashes, 0f)); // flavour: float (AWT's)
            }
        }
        VectorGraphicsEncoder.saveVectorGraphic(chart, stem.toString(), VectorGraphicsEncoder.VectorGraphicsFormat.SVG);
        return 1;
    }
}
