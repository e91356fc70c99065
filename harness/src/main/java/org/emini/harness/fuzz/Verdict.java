package org.emini.harness.fuzz;

/**
 * The outcome of one input, who is answerable for it, and what happened.
 *
 * @param outcome the category
 * @param blame {@code harness} or {@code engine}: whose code threw, or whose check let the value through
 * @param stage where it happened ({@code load}, {@code build}, {@code tick}, {@code read}, a call's name)
 * @param message the exception or problem, one line
 */
public record Verdict(Outcome outcome, String blame, String stage, String message) {
    /** Who answers for a failure. */
    public static final String HARNESS = "harness";
    /** Who answers for a failure. */
    public static final String ENGINE = "engine";

    static Verdict clean(String stage, String message) {
        return new Verdict(Outcome.CLEAN, "", stage, message);
    }

    static Verdict accepted(String stage) {
        return new Verdict(Outcome.ACCEPTED, "", stage, "");
    }

    /** A failure caused by a throwable: blamed on the code at the top of its stack (harness or engine). */
    static Verdict thrown(Outcome outcome, String stage, Throwable e) {
        return new Verdict(outcome, blame(e), stage, oneLine(e));
    }

    /** The exception and the first frame in Emini's code, in one line. */
    static String oneLine(Throwable e) {
        StringBuilder s = new StringBuilder(String.valueOf(e));
        for (StackTraceElement f : e.getStackTrace()) {
            if (f.getClassName().startsWith("org.emini.")) {
                s.append(" at ").append(f);
                break;
            }
        }
        return s.toString().replace('\n', ' ').replace('\t', ' ');
    }

    /** The harness when its code is nearest the throw, the engine when the engine's is; the harness (which made the call) when neither is on the stack. */
    static String blame(Throwable e) {
        for (StackTraceElement f : e.getStackTrace()) {
            if (f.getClassName().startsWith("org.emini.harness.")) {
                return HARNESS;
            }
            if (f.getClassName().startsWith("org.emini.")) {
                return ENGINE;
            }
        }
        return HARNESS;
    }

    /** The verdict as one tab-separated line (the worker's answer). */
    String encode() {
        return outcome.name() + '\t' + blame + '\t' + stage + '\t' + message.replace('\n', ' ').replace('\t', ' ');
    }

    static Verdict decode(String line) {
        String[] p = line.split("\t", 4);
        return new Verdict(Outcome.valueOf(p[0]), p[1], p[2], p.length > 3 ? p[3] : "");
    }
}
