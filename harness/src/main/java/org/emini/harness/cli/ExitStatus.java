package org.emini.harness.cli;

/**
 * The harness's exit statuses, the same for every command (harness/README.md, Exit status). What 1
 * means is each command's own finding (an invalid scene, a regression, a fuzz crash); the others
 * say the command could not do its work, each with one line on stderr.
 */
public final class ExitStatus {
    private ExitStatus() {
    }

    /** The statuses as {@code --help} lists them (every command's help ends with this list). */
    static final java.util.Map<String, String> HELP = helpList();

    private static java.util.Map<String, String> helpList() {
        java.util.Map<String, String> m = new java.util.LinkedHashMap<>();
        m.put(" 0", "done, nothing found");
        m.put(" 1", "done, and the command found what it looks for: an invalid scene (validate, expand, convert), a "
                + "scene that is FAIL or ERROR (run), a scene that could not be compared (compare), a regression "
                + "beyond the tolerances (diff), a fuzz failure (fuzz)");
        m.put(" 2", "the command line is wrong: an unknown option, a bad value, PATHS or -k matching no scene");
        m.put(" 3", "a file or folder could not be read or written");
        m.put(" 4", "out of memory: give the JVM more (EMINI_JAVA_OPTS=-Xmx4g, or java -Xmx4g -jar ...)");
        m.put("70", "an internal error of the harness, named in one line (EMINI_DEBUG=1 adds the stack trace)");
        return java.util.Collections.unmodifiableMap(m);
    }

    /** Adds the list of exit statuses to the help of a command and of all its subcommands. */
    static void describe(picocli.CommandLine cmd) {
        cmd.getCommandSpec().usageMessage().exitCodeListHeading("%nExit status:%n").exitCodeList(HELP);
        cmd.getSubcommands().values().forEach(ExitStatus::describe);
    }

    /** Done, nothing to report. */
    public static final int OK = 0;
    /** Done, and the command found what it looks for: an invalid scene, a failing scene, a fuzz failure. */
    public static final int FINDINGS = 1;
    /** The command line is wrong: an unknown option, a bad value, PATHS with no scene file in them. */
    public static final int USAGE = 2;
    /** A file or folder could not be read or written (a missing input, reports under a file, a full disk). */
    public static final int IO = 3;
    /** The Java heap ran out: the inputs are too big for it (give the JVM more with EMINI_JAVA_OPTS=-Xmx…). */
    public static final int OUT_OF_MEMORY = 4;
    /** A defect of the harness: one line names it; EMINI_DEBUG=1 prints the stack trace as well. */
    public static final int INTERNAL = 70;
}
