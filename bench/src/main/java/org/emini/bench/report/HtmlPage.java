package org.emini.bench.report;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.emini.bench.run.Measurement;
import org.emini.harness.report.LogLogSlope;

/** The static report page: opens from the file system, no script, plots as SVG files beside it. */
public final class HtmlPage {
    private HtmlPage() {
    }

    /** The page for a report; chart stems may be null when there was nothing to plot. */
    public static String render(BenchReport r, List<String> engines, String scenesChart, String scalingChart) {
        StringBuilder h = new StringBuilder();
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Emini benchmarks</title>\n<style>")
            .append("body{font-family:system-ui,sans-serif;margin:2em;max-width:1200px;color:#222}")
            .append("table{border-collapse:collapse;margin:0.5em 0 1.5em}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}")
            .append("th{background:#f3f3f3}td.l,th.l{text-align:left}tr.emini td{background:#fff6f0}")
            .append(".stable{color:#1a7f37}.drifted{color:#b35900}.collapsed,.escaped,.stretched,.slowed,.non-finite,.error{color:#c00;font-weight:bold}")
            .append(".muted{color:#777}code{background:#f3f3f3;padding:0 3px}</style></head><body>\n");
        h.append("<h1>Emini benchmarks</h1>\n<p>").append(esc(r.generated())).append(" · mode <b>").append(r.mode())
            .append("</b> · ").append(esc(r.runTime())).append("</p>\n");
        if ("quick".equals(r.mode())) {
            h.append("<p><b>Quick mode</b>: short iterations in one JVM and a short preroll: a check that everything runs, ")
                .append("not figures to publish.</p>\n");
        }
        h.append("<h2>Machine</h2>\n<table>");
        for (Map.Entry<String, Object> e : r.machine().entrySet()) {
            h.append("<tr><th class=l>").append(esc(e.getKey())).append("</th><td class=l>").append(esc(String.valueOf(e.getValue()))).append("</td></tr>");
        }
        h.append("<tr><th class=l>load average at the end</th><td class=l>").append(fmt(r.loadAverageEnd())).append("</td></tr>");
        h.append("<tr><th class=l>JMH</th><td class=l>").append(esc(String.valueOf(r.jmh()))).append("</td></tr></table>\n");
        h.append("<p>Each figure is one tick of a scene after an untimed preroll (the scene's run duration: the pyramids have settled, ")
            .append("the rain has landed). <b>CPU ms/tick</b> is the benchmark thread's CPU time over JMH's measurement iterations, ")
            .append("the figure comparisons use: on a shared machine it moves less than wall time. <b>Wall</b> is JMH's score ")
            .append("(mean ± 99.9% interval, and the median iteration). <b>Alloc</b> is JMH's gc.alloc.rate.norm (Java heap only; ")
            .append("libGDX's native Box2D allocates outside it; JMH's own threads add a little); <b>thread B/tick</b> is the benchmark thread's exact allocation counter over the measured ticks. <b>Check</b> judges the scene after the preroll, the same ticks in every engine ")
            .append("(see bench/ENGINES.md); a scene that collapsed does not count as fast. <b>vs Emini</b> is the engine's CPU time ")
            .append("divided by Emini's: above 1, Emini is faster.</p>\n");

        h.append("<h2>Summary: CPU ms per tick</h2>\n<table><tr><th class=l>scene</th>");
        for (String e : engines) {
            h.append("<th>").append(esc(e)).append("</th>");
        }
        h.append("</tr>\n");
        for (BenchReport.SceneEntry s : r.scenes()) {
            h.append("<tr><td class=l>").append(esc(s.title())).append("</td>");
            if (!"ran".equals(s.status())) {
                h.append("<td class=\"l muted\" colspan=").append(engines.size()).append(">pending: ").append(esc(s.message())).append("</td></tr>\n");
                continue;
            }
            for (String e : engines) {
                Measurement m = find(s.results(), e);
                h.append("<td>").append(summaryCell(m)).append("</td>");
            }
            h.append("</tr>\n");
        }
        h.append("</table>\n");
        if (scenesChart != null) {
            h.append("<p><img src=\"").append(scenesChart).append(".svg\" alt=\"time per tick per scene and engine\" width=900></p>\n");
        }

        for (BenchReport.SceneEntry s : r.scenes()) {
            h.append("<h2>").append(esc(s.title())).append(" <span class=muted><code>").append(esc(s.id())).append("</code></span></h2>\n");
            if (!"ran".equals(s.status())) {
                h.append("<p class=muted>Pending: ").append(esc(s.message())).append("</p>\n");
                continue;
            }
            h.append(table(s.results(), engines));
        }

        h.append("<h2>Scaling: rain, time per tick against body count</h2>\n");
        if (scalingChart != null) {
            h.append("<p><img src=\"").append(scalingChart).append(".svg\" alt=\"scaling, log-log\" width=900></p>\n");
        }
        h.append(scalingTable(r.scaling(), engines));
        h.append("<h2>Engines in a process of their own</h2>\n");
        r.external().forEach((e, o) -> h.append("<p><b>").append(esc(e)).append("</b>: ").append(esc(String.valueOf(o.get("status"))))
            .append(": ").append(esc(String.valueOf(o.get("message")))).append("</p>\n"));
        h.append("<h2>Engine settings</h2>\n<table><tr><th class=l>engine</th><th class=l>settings</th></tr>");
        Map<String, String> settings = new LinkedHashMap<>();
        for (BenchReport.SceneEntry s : r.scenes()) {
            for (Measurement m : s.results()) {
                if (m.settings() != null) {
                    settings.putIfAbsent(m.engine(), m.settings());
                }
            }
        }
        for (Map.Entry<String, String> e : settings.entrySet()) {
            h.append("<tr><td class=l>").append(esc(e.getKey())).append("</td><td class=l>").append(esc(e.getValue())).append("</td></tr>");
        }
        h.append("</table>\n<p class=muted>Raw figures: <a href=\"bench.json\">bench.json</a>; per-run scene checks in <code>checks/</code>, ")
            .append("JMH logs in <code>jmh/</code>.</p>\n</body></html>\n");
        return h.toString();
    }

    private static String summaryCell(Measurement m) {
        if (m == null) {
            return "<span class=muted>—</span>";
        }
        if (!"ok".equals(m.status())) {
            return "<span class=" + cls(m.status()) + " title=\"" + esc(m.message()) + "\">" + esc(m.status()) + "</span>";
        }
        String v = m.verdict();
        return fmt(m.cost()) + (v == null || "stable".equals(v) ? "" : " <span class=" + v + ">" + v + "</span>");
    }

    private static String table(List<Measurement> ms, List<String> engines) {
        Measurement emini = find(ms, "emini");
        StringBuilder h = new StringBuilder("<table><tr><th class=l>engine</th><th>CPU ms/tick</th><th>vs Emini</th><th>wall ms/tick</th>")
            .append("<th>wall median</th><th>µs per body</th><th>alloc B/tick (JMH)</th><th>thread B/tick</th><th>from start ms/tick</th><th class=l>check</th><th class=l>after the timed run</th></tr>\n");
        for (String e : engines) {
            Measurement m = find(ms, e);
            if (m == null) {
                continue;
            }
            h.append("<tr").append("emini".equals(e) ? " class=emini" : "").append("><td class=l>").append(esc(e)).append("</td>");
            if (!"ok".equals(m.status())) {
                h.append("<td class=\"l ").append(cls(m.status())).append("\" colspan=10>").append(esc(m.status())).append(": ").append(esc(m.message())).append("</td></tr>\n");
                continue;
            }
            h.append("<td>").append(fmt(m.cost())).append("</td><td>");
            if (emini != null && emini.cost() != null && m.cost() != null && !"emini".equals(e)) {
                h.append(String.format(Locale.ROOT, "%.2f×", m.cost() / emini.cost()));
            }
            h.append("</td><td>").append(fmt(m.msPerTick())).append(m.msPerTickError() == null ? "" : " ± " + fmt(m.msPerTickError()))
                .append("</td><td>").append(fmt(m.msPerTickMedian())).append("</td><td>").append(fmt(m.usPerBody()))
                .append("</td><td>").append(bytes(m.allocBytesPerTick())).append("</td><td>").append(bytes(m.threadBytesPerTick())).append("</td><td>").append(fmt(m.prerollMsPerTick()))
                .append("</td><td class=l>").append(check(m.check())).append("</td><td class=l>").append(check(m.afterRun())).append("</td></tr>\n");
        }
        return h.append("</table>\n").toString();
    }

    private static String scalingTable(List<Measurement> scaling, List<String> engines) {
        List<Long> counts = new ArrayList<>();
        for (Measurement m : scaling) {
            if (m.dynamicBodies() > 0 && !counts.contains(m.dynamicBodies())) {
                counts.add(m.dynamicBodies());
            }
        }
        StringBuilder h = new StringBuilder("<table><tr><th class=l>engine</th>");
        for (long c : counts) {
            h.append("<th>").append(c).append("</th>");
        }
        h.append("<th>slope</th></tr>\n");
        for (String e : engines) {
            h.append("<tr").append("emini".equals(e) ? " class=emini" : "").append("><td class=l>").append(esc(e)).append("</td>");
            for (long c : counts) {
                Measurement m = null;
                for (Measurement x : scaling) {
                    if (x.engine().equals(e) && x.dynamicBodies() == c) {
                        m = x;
                    }
                }
                h.append("<td>").append(summaryCell(m)).append("</td>");
            }
            h.append("<td>").append(fmt(slope(scaling, e))).append("</td></tr>\n");
        }
        return h.append("</table>\n<p class=muted>CPU ms per tick by dynamic body count; slope: least-squares slope of ")
            .append("log(time) against log(bodies) (1 is linear).</p>\n").toString();
    }

    /** Least-squares slope of log time against log bodies for an engine, or null. */
    public static Double slope(List<Measurement> scaling, String engine) {
        LogLogSlope s = new LogLogSlope();
        for (Measurement m : scaling) {
            if (m.engine().equals(engine) && m.cost() != null) {
                s.add(m.dynamicBodies(), m.cost());
            }
        }
        return s.slope();
    }

    private static String check(Map<String, Object> c) {
        if (c == null) {
            return "";
        }
        String v = String.valueOf(c.get("verdict"));
        StringBuilder s = new StringBuilder("<span class=").append(v).append(">").append(v).append("</span> <span class=muted>after ")
            .append(num(c.get("ticks"), "%.0f")).append(" ticks: dx ").append(num(c.get("maxDxPx"), "%.1f")).append(" px, dy ")
            .append(num(c.get("maxDyPx"), "%.1f")).append(" px, angle ").append(num(c.get("maxAngle"), "%.3f")).append(" rad");
        Object esc = c.get("escaped");
        if (esc instanceof Number && ((Number) esc).intValue() > 0) {
            s.append(", escaped ").append(num(esc, "%.0f"));
        }
        Object je = c.get("maxJointErrorPx");
        if (je instanceof Number && ((Number) je).doubleValue() > 0) {
            s.append(", joint error ").append(num(je, "%.2f")).append(" px");
        }
        Object np = c.get("particles");
        if (np instanceof Number && ((Number) np).intValue() > 0) {
            s.append(", ").append(num(np, "%.0f")).append(" particles");
        }
        Object asleep = c.get("asleep");
        if (asleep instanceof Number && ((Number) asleep).intValue() >= 0) {
            s.append(", ").append(num(asleep, "%.0f")).append(" asleep");
        }
        Object me = c.get("motorSpeedError");
        if (me instanceof Number && ((Number) me).doubleValue() != 0) {
            s.append(", container ω off by ").append(num(((Number) me).doubleValue() * 100, "%.2g")).append("%");
        }
        s.append(", max speed ").append(num(c.get("maxSpeed"), "%.0f")).append(" px/s</span>");
        return s.toString();
    }

    private static Measurement find(List<Measurement> ms, String engine) {
        for (Measurement m : ms) {
            if (m.engine().equals(engine)) {
                return m;
            }
        }
        return null;
    }

    private static String cls(String status) {
        return "unsupported".equals(status) || "skipped".equals(status) ? "muted" : "error";
    }

    private static String num(Object o, String f) {
        return o instanceof Number ? String.format(Locale.ROOT, f, ((Number) o).doubleValue()) : "?";
    }

    static String fmt(Double d) {
        if (d == null || d.isNaN()) {
            return "";
        }
        double a = Math.abs(d);
        String f = a >= 100 ? "%.0f" : a >= 10 ? "%.1f" : a >= 1 ? "%.2f" : "%.3f";
        return String.format(Locale.ROOT, f, d);
    }

    static String bytes(Double b) {
        if (b == null) {
            return "";
        }
        if (b < 0.5) {
            return "0";
        }
        if (b < 1e4) {
            return String.format(Locale.ROOT, "%.0f", b);
        }
        if (b < 1e7) {
            return String.format(Locale.ROOT, "%.1f K", b / 1e3);
        }
        return String.format(Locale.ROOT, "%.1f M", b / 1e6);
    }

    private static String esc(String s) {
        return s == null ? "" : s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
