package org.emini.harness.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import org.emini.harness.load.IoText;
import picocli.CommandLine;
import picocli.CommandLine.IExecutionExceptionHandler;
import picocli.CommandLine.IParameterExceptionHandler;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ParseResult;

/**
 * Turns what stops a command into one line on stderr and an {@link ExitStatus}: never a stack trace for
 * a user's mistake or a full disk. Causes are looked through (a worker thread's failure arrives wrapped
 * in an ExecutionException), so an OutOfMemoryError or an IOException is named as such wherever it happened.
 */
final class Failures implements IExecutionExceptionHandler, IParameterExceptionHandler {

    @Override
    public int handleParseException(ParameterException e, String[] args) {
        CommandLine cmd = e.getCommandLine();
        PrintWriter err = cmd.getErr();
        err.println(name(cmd) + ": " + e.getMessage());
        err.println("(" + name(cmd) + " --help for the options)");
        err.flush();
        return ExitStatus.USAGE;
    }

    @Override
    public int handleExecutionException(Exception e, CommandLine cmd, ParseResult parsed) {
        return report(e, cmd);
    }

    /** Reports a failure of a command (also an Error, which picocli lets through) and gives its status. */
    static int report(Throwable e, CommandLine cmd) {
        PrintWriter err = cmd.getErr();
        int status;
        String line;
        Throwable cause = find(e, ParameterException.class);
        if (cause != null) {
            line = cause.getMessage();
            status = ExitStatus.USAGE;
        } else if ((cause = find(e, OutOfMemoryError.class)) != null) {
            line = "out of memory (" + cause.getMessage() + "): the inputs need more heap than this JVM has "
                    + Runtime.getRuntime().maxMemory() / (1 << 20) + " MB; set EMINI_JAVA_OPTS=-Xmx… and run again";
            status = ExitStatus.OUT_OF_MEMORY;
        } else if ((cause = find(e, IOException.class)) != null) {
            line = IoText.describe((IOException) cause);
            status = ExitStatus.IO;
        } else {
            line = "internal error: " + e + (e.getStackTrace().length > 0 ? " at " + e.getStackTrace()[0] : "")
                    + " (a defect of the harness; EMINI_DEBUG=1 prints the stack trace)";
            status = ExitStatus.INTERNAL;
        }
        err.println(name(cmd) + ": " + line);
        if ("1".equals(System.getenv("EMINI_DEBUG"))) {
            e.printStackTrace(err);
        }
        err.flush();
        return status;
    }

    private static Throwable find(Throwable e, Class<? extends Throwable> type) {
        for (Throwable t = e; t != null; t = t.getCause() == t ? null : t.getCause()) {
            if (type.isInstance(t)) {
                return t;
            }
            if (t instanceof UncheckedIOException u && type.isInstance(u.getCause())) {
                return u.getCause();
            }
        }
        return null;
    }

    private static String name(CommandLine cmd) {
        return cmd.getCommandSpec().qualifiedName();
    }
}
