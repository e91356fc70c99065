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
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * The child JVM that judges fuzz inputs, with a bounded heap, so that an input that hangs can be
 * killed and one that exhausts memory cannot take the fuzzer with it. Reads one base64 input per line
 * on stdin, answers one {@link Verdict} line on stdout ({@code ready} first). After an Error (out of
 * memory, stack overflow) it answers and exits: the parent starts a fresh one. An input still being
 * judged after the time limit is answered as a hang, blamed on the code its thread is stuck in, and
 * the worker exits with the stuck thread.
 *
 * <p>Arguments: the target ({@code scenarios}, {@code phy}, {@code setters}), the scenario schema, ticks,
 * the time limit per input in seconds.
 */
public final class FuzzWorker {
    private FuzzWorker() {
    }

    /** Runs the worker loop until stdin closes. */
    public static void main(String[] args) throws IOException, ReflectiveOperationException, InterruptedException {
        PrintStream answers = new PrintStream(new FileOutputStream(FileDescriptor.out), true, StandardCharsets.UTF_8);
        // Whatever the code under test prints must not be taken for an answer.
        System.setOut(System.err);
        Checker checker = FuzzTarget.checker(args[0], Path.of(args[1]), Integer.parseInt(args[2]));
        long limit = Long.parseLong(args[3]);
        ExecutorService checking = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "fuzz-check");
            t.setDaemon(true);
            return t;
        });
        Thread[] worker = new Thread[1];
        answers.println("ready");
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        for (String line; (line = in.readLine()) != null;) {
            byte[] input = Base64.getDecoder().decode(line);
            Future<Verdict> f = checking.submit(() -> {
                worker[0] = Thread.currentThread();
                try {
                    return checker.check(input);
                } catch (Throwable t) {
                    return Verdict.thrown(Outcome.CRASH, "checker", t);
                }
            });
            Verdict v;
            try {
                v = f.get(limit, TimeUnit.SECONDS);
            } catch (TimeoutException e) {
                // Where the check is stuck says whose the hang is; the JVM goes with the stuck thread.
                answers.println(hang(worker[0], limit).encode());
                System.exit(4);
                return;
            } catch (ExecutionException e) {
                v = Verdict.thrown(Outcome.CRASH, "checker", e.getCause());
            }
            answers.println(v.encode());
            if (fatal(v)) {
                System.exit(3);
            }
        }
    }

    /** A hang, blamed on the code the stuck thread is in. */
    static Verdict hang(Thread stuck, long seconds) {
        Throwable where = new Throwable("busy");
        where.setStackTrace(stuck.getStackTrace());
        String at = "";
        for (StackTraceElement e : where.getStackTrace()) {
            if (e.getClassName().startsWith("org.emini.")) {
                at = " in " + e;
                break;
            }
        }
        return new Verdict(Outcome.HANG, Verdict.blame(where), "check", "no answer within " + seconds + " s; busy" + at);
    }

    /** Whether the worker met an Error after which its JVM is not to be trusted. */
    static boolean fatal(Verdict v) {
        return v.message().startsWith("java.lang.OutOfMemoryError") || v.message().startsWith("java.lang.StackOverflowError")
                || v.message().startsWith("java.lang.InternalError");
    }
}
