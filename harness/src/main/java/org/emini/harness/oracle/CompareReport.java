package org.emini.harness.oracle;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Locale;

/**
 * How the comparison's reports write a figure ({@link MultiComparison} writes compare.json and
 * summary.md; formats in harness/README.md, compare).
 */
final class CompareReport {
    private CompareReport() {
    }

    /** Four significant digits, no exponent for ordinary magnitudes; "-" for a missing figure. */
    static String fmt(double v) {
        if (Double.isNaN(v)) {
            return "-";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        if (v == 0) {
            return "0";
        }
        double a = Math.abs(v);
        if (a >= 1e-3 && a < 1e7) {
            return new BigDecimal(v).round(new MathContext(4)).stripTrailingZeros().toPlainString();
        }
        return String.format(Locale.ROOT, "%.3e", v);
    }
}
