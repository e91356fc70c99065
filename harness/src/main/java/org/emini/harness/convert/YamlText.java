package org.emini.harness.convert;

import java.math.BigDecimal;

/** Writes the scalars of a scene file: numbers exactly and without exponents, strings quoted when needed. */
final class YamlText {
    private YamlText() {
    }

    /**
     * A number as the shortest decimal that reads back as the same double, without an exponent
     * (YAML 1.1 reads {@code 1.0E10} as a string). Fixed-point values (raw / 4096) are exact.
     */
    static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return new BigDecimal(Double.toString(v)).stripTrailingZeros().toPlainString();
    }

    /** {@code [x, y]}. */
    static String vec(double x, double y) {
        return "[" + num(x) + ", " + num(y) + "]";
    }

    /** A name: plain when it is a simple identifier YAML reads as a string, else double-quoted. */
    static String name(String s) {
        boolean plain = s.matches("[A-Za-z_][A-Za-z0-9_]*")
                && !s.toLowerCase(java.util.Locale.ROOT).matches("y|n|yes|no|true|false|on|off|null");
        return plain ? s : quote(s);
    }

    /** A double-quoted string with JSON escapes, which YAML reads the same. */
    static String quote(String s) {
        StringBuilder b = new StringBuilder("\"");
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"':
                    b.append("\\\"");
                    break;
                case '\\':
                    b.append("\\\\");
                    break;
                case '\n':
                    b.append("\\n");
                    break;
                case '\r':
                    b.append("\\r");
                    break;
                case '\t':
                    b.append("\\t");
                    break;
                default:
                    if (c < 0x20 || c == 0x7F || Character.isSurrogate(c) && !validSurrogate(s, i)) {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
            }
        }
        return b.append('"').toString();
    }

    private static boolean validSurrogate(String s, int i) {
        char c = s.charAt(i);
        return Character.isHighSurrogate(c) ? i + 1 < s.length() && Character.isLowSurrogate(s.charAt(i + 1))
                : i > 0 && Character.isHighSurrogate(s.charAt(i - 1));
    }
}
