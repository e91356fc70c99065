package org.emini.harness.load;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.Locale;

/**
 * Reads YAML numbers exactly (BigInteger, BigDecimal) and refuses those the engine would change in
 * silence: the engine computes in float, so a value beyond ±3.4e38 would become infinite and a
 * non-zero value below 1.4e-45 would become 0 (1e-400 is not 0 ticks of a run, it is a mistake).
 * Integer fields have bounds in the schema, checked on the exact value before anything narrows it.
 */
final class Numbers {
    /** Characters of a number literal; no scene needs more, and a longer one costs time to convert. */
    static final int MAX_LENGTH = 100;

    private static final BigDecimal LARGEST = new BigDecimal(Float.MAX_VALUE);
    private static final BigDecimal SMALLEST = new BigDecimal(Float.MIN_VALUE);

    private Numbers() {
    }

    /** A number or why it is refused. */
    record Read(Number value, String problem) {
    }

    /** A scalar SnakeYAML resolved as an integer. */
    static Read integer(String text) {
        String s = text.replace("_", "");
        if (s.length() > MAX_LENGTH) {
            return refused("a number of " + s.length() + " characters (at most " + MAX_LENGTH + ")");
        }
        String digits = s.startsWith("+") || s.startsWith("-") ? s.substring(1) : s;
        if (digits.length() > 1 && digits.charAt(0) == '0' && Character.isDigit(digits.charAt(1))) {
            return refused(text + " has a leading zero, which YAML 1.1 reads as octal; write it without the zero");
        }
        BigInteger value;
        try {
            value = new BigInteger(s.startsWith("+") ? s.substring(1) : s);
        } catch (NumberFormatException e) {
            return refused("not a number the harness can read: " + text + " (write decimal numbers)");
        }
        return ranged(new BigDecimal(value), value, text);
    }

    /** A scalar SnakeYAML resolved as a float. */
    static Read decimal(String text) {
        String s = text.replace("_", "").toLowerCase(Locale.ROOT);
        if (s.contains("inf") || s.contains("nan")) {
            return refused("not a finite number: " + text);
        }
        if (s.length() > MAX_LENGTH) {
            return refused("a number of " + s.length() + " characters (at most " + MAX_LENGTH + ")");
        }
        BigDecimal value;
        try {
            value = new BigDecimal(s);
        } catch (NumberFormatException | ArithmeticException e) {
            return refused("not a number the harness can read: " + text);
        }
        return ranged(value, value, text);
    }

    private static Read ranged(BigDecimal exact, Number value, String text) {
        BigDecimal abs = exact.abs();
        if (abs.compareTo(LARGEST) > 0) {
            return refused(text + " is out of range: the engine computes in float, whose largest value is "
                    + Float.MAX_VALUE);
        }
        if (abs.signum() != 0 && abs.compareTo(SMALLEST) < 0) {
            return refused(text + " is too small: in float (the engine's precision) it is 0; the smallest "
                    + "non-zero value is " + Float.MIN_VALUE);
        }
        return new Read(value, null);
    }

    private static Read refused(String problem) {
        return new Read(null, problem);
    }
}
