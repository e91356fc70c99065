package org.emini.harness.cli;

/**
 * The harness's exit statuses, the same for every command (harness/README.md, Exit status). What 1
 * means is each command's own finding (an invalid scene, a regression, a fuzz crash); the others
 * say the command could not do its work, each with one line on stderr.
 */
public final class ExitStatus {
    private ExitStatus() {
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
