package org.emini.harness.report;

import java.util.Locale;
import org.emini.harness.metrics.PenetrationPair;
import org.emini.harness.run.SceneResult;

/** The one-line-per-scene console format. */
public final class ConsoleTable {
    private ConsoleTable() {
    }

    /** One line: status, scene, size, time, the deepest overlapping pair (with penetration) and the message when there is one. */
    public static String line(SceneResult r, int nameWidth) {
        String size = r.ticks() > 0
                ? String.format(Locale.ROOT, "%6d bodies %6d ticks %8.2f s", r.bodies(), r.ticks(),
                        (r.buildMillis() + r.runMillis()) / 1000)
                : String.format(Locale.ROOT, "%6d bodies %30s", r.bodies(), "");
        String line = String.format(Locale.ROOT, "%-11s %-" + nameWidth + "s %s", r.status().label(), r.scene(), size);
        if (!r.penetrationPairs().isEmpty()) {
            PenetrationPair p = r.penetrationPairs().get(0);
            line += String.format(Locale.ROOT, "  deepest overlap %s–%s %.3g px", p.a(), p.b(), p.max());
        }
        return r.message().isEmpty() ? line : line + "  " + r.message();
    }
}
