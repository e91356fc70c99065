package org.emini.bench.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.emini.bench.run.Measurement;

/** The report's tables as Markdown ({@code reports/bench/RESULTS.md}), for issue notes and bench/RESULTS.md. */
public final class MarkdownTables {
    private MarkdownTables() {
    }

    /** The summary, one table per scene, and the scaling table. */
    public static String render(BenchReport r, List<String> engines) {
        StringBuilder md = new StringBuilder();
        Map<String, Object> m = r.machine();
        md.append("Measured ").append(r.generated()).append(" (").append(r.mode()).append(" mode, ")
            .append(r.runTime()).append(") on ").append(m.get("cpu")).append(", ")
            .append(m.get("cores")).append(" cores, ").append(m.get("memoryGiB")).append(" GiB, ").append(m.get("jvm"))
            .append("; load average ").append(HtmlPage.fmt(((Number) m.get("loadAverage")).doubleValue())).append(" at the start, ")
            .append(HtmlPage.fmt(r.loadAverageEnd())).append(" at the end. JMH ").append(r.jmh()).append(".\n\n");
        md.append("CPU ms per tick (the benchmark thread's CPU time); a verdict other than stable is shown next to the time.\n\n");
        md.append("| scene |");
        for (String e : engines) {
            md.append(' ').append(e).append(" |");
        }
        md.append("\n|---|");
        for (int i = 0; i < engines.size(); i++) {
            md.append("---|");
        }
        md.append('\n');
        for (BenchReport.SceneEntry s : r.scenes()) {
            md.append("| ").append(s.title()).append(" |");
            if (!"ran".equals(s.status())) {
                md.append(" pending: ").append(s.message()).append(" |");
                for (int i = 1; i < engines.size(); i++) {
                    md.append(" |");
                }
                md.append('\n');
                continue;
            }
            for (String e : engines) {
                md.append(' ').append(cell(find(s.results(), e))).append(" |");
            }
            md.append('\n');
        }
        for (BenchReport.SceneEntry s : r.scenes()) {
            if (!"ran".equals(s.status())) {
                continue;
            }
            md.append("\n### ").append(s.title()).append(" (`").append(s.id()).append("`)\n\n")
                .append("| engine | CPU ms/tick | vs Emini | wall ms/tick (mean ± err, median) | µs/body | alloc B/tick (JMH; thread) | check after preroll | after the timed run |\n")
                .append("|---|---|---|---|---|---|---|---|\n");
            Measurement emini = find(s.results(), "emini");
            for (String e : engines) {
                Measurement x = find(s.results(), e);
                if (x == null) {
                    continue;
                }
                if (!"ok".equals(x.status())) {
                    md.append("| ").append(e).append(" | ").append(x.status()).append(": ").append(x.message()).append(" | | | | | | |\n");
                    continue;
                }
                String ratio = emini != null && emini.cost() != null && !"emini".equals(e)
                    ? String.format(Locale.ROOT, "%.2f×", x.cost() / emini.cost()) : "";
                md.append("| ").append(e).append(" | ").append(HtmlPage.fmt(x.cost())).append(" | ").append(ratio).append(" | ")
                    .append(HtmlPage.fmt(x.msPerTick())).append(x.msPerTickError() == null ? "" : " ± " + HtmlPage.fmt(x.msPerTickError()))
                    .append(", ").append(HtmlPage.fmt(x.msPerTickMedian())).append(" | ").append(HtmlPage.fmt(x.usPerBody())).append(" | ")
                    .append(HtmlPage.bytes(x.allocBytesPerTick())).append("; ").append(HtmlPage.bytes(x.threadBytesPerTick())).append(" | ")
                    .append(check(x.check())).append(" | ").append(check(x.afterRun())).append(" |\n");
            }
        }
        if (!r.scaling().isEmpty()) {
            List<Long> counts = new ArrayList<>();
            for (Measurement x : r.scaling()) {
                if (x.dynamicBodies() > 0 && !counts.contains(x.dynamicBodies())) {
                    counts.add(x.dynamicBodies());
                }
            }
            md.append("\n### Scaling: rain, CPU ms per tick by body count\n\n| engine |");
            for (long c : counts) {
                md.append(' ').append(c).append(" |");
            }
            md.append(" slope |\n|---|");
            for (int i = 0; i <= counts.size(); i++) {
                md.append("---|");
            }
            md.append('\n');
            for (String e : engines) {
                md.append("| ").append(e).append(" |");
                for (long c : counts) {
                    Measurement f = null;
                    for (Measurement x : r.scaling()) {
                        if (x.engine().equals(e) && x.dynamicBodies() == c) {
                            f = x;
                        }
                    }
                    md.append(' ').append(cell(f)).append(" |");
                }
                md.append(' ').append(HtmlPage.fmt(HtmlPage.slope(r.scaling(), e))).append(" |\n");
            }
        }
        md.append('\n');
        r.external().forEach((e, o) -> md.append(e).append(": ").append(o.get("status")).append(": ").append(o.get("message")).append("\n\n"));
        return md.toString();
    }

    private static String cell(Measurement x) {
        if (x == null) {
            return "—";
        }
        if (!"ok".equals(x.status())) {
            return x.status();
        }
        String v = x.verdict();
        return HtmlPage.fmt(x.cost()) + (v == null || "stable".equals(v) ? "" : " **" + v + "**");
    }

    private static String check(Map<String, Object> c) {
        if (c == null) {
            return "";
        }
        StringBuilder s = new StringBuilder(String.valueOf(c.get("verdict"))).append(String.format(Locale.ROOT,
            " (%.0f ticks; dx %.1f, dy %.1f px, %.3f rad", num(c.get("ticks")), num(c.get("maxDxPx")), num(c.get("maxDyPx")), num(c.get("maxAngle"))));
        if (num(c.get("maxJointErrorPx")) > 0) {
            s.append(String.format(Locale.ROOT, ", joint error %.1f px", num(c.get("maxJointErrorPx"))));
        }
        if (num(c.get("escaped")) > 0) {
            s.append(String.format(Locale.ROOT, ", %.0f escaped", num(c.get("escaped"))));
        }
        if (num(c.get("particles")) > 0) {
            s.append(String.format(Locale.ROOT, ", %.0f particles", num(c.get("particles"))));
        }
        if (c.get("asleep") instanceof Number && num(c.get("asleep")) >= 0) {
            s.append(String.format(Locale.ROOT, ", %.0f asleep", num(c.get("asleep"))));
        }
        if (c.get("motorSpeedError") instanceof Number && num(c.get("motorSpeedError")) != 0) {
            s.append(String.format(Locale.ROOT, ", container ω off by %.2g%%", num(c.get("motorSpeedError")) * 100));
        }
        return s.append(')').toString();
    }

    private static double num(Object o) {
        return o instanceof Number ? ((Number) o).doubleValue() : Double.NaN;
    }

    private static Measurement find(List<Measurement> ms, String engine) {
        for (Measurement x : ms) {
            if (x.engine().equals(engine)) {
                return x;
            }
        }
        return null;
    }
}
