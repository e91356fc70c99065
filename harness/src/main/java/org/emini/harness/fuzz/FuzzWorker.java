package org.emini.harness.fuzz;

import java.io.BufferedReader;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Base64;

/**
 * The child JVM that judges fuzz inputs, with a bounded heap, so that an input that hangs can be
 * killed and one that exhausts memory cannot take the fuzzer with it. Reads one base64 input per line
 * on stdin, answers one {@link Verdict} line on stdout ({@code ready} first). After an Error (out of
 * memory, stack overflow) it answers and exits: the parent starts a fresh one.
 *
 * <p>Arguments: the target ({@code scenarios}, {@code phy}, {@code setters}), the scenario schema, ticks.
 */
public final class FuzzWorker {
    private FuzzWorker() {
    }

    /** Runs the worker loop until stdin closes. */
    public static void main(String[] args) throws IOException, ReflectiveOperationException {
        PrintStream answers = new PrintStream(new FileOutputStream(FileDescriptor.out), true, StandardCharsets.UTF_8);
        // Whatever the code under test prints must not be taken for an answer.
        System.setOut(System.err);
        Checker checker = FuzzTarget.checker(args[0], Path.of(args[1]), Integer.parseInt(args[2]));
        answers.println("ready");
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        for (String line; (line = in.readLine()) != null;) {
            Verdict v;
            try {
                v = checker.check(Base64.getDecoder().decode(line));
            } catch (Throwable t) {
                v = Verdict.thrown(Outcome.CRASH, "checker", t);
            }
            answers.println(v.encode());
            if (fatal(v)) {
                System.exit(3);
            }
        }
    }

    /** Whether the worker met an Error after which its JVM is not to be trusted. */
    static boolean fatal(Verdict v) {
        return v.message().startsWith("java.lang.OutOfMemoryError") || v.message().startsWith("java.lang.StackOverflowError")
                || v.message().startsWith("java.lang.InternalError");
    }
}
