package org.emini.harness.fuzz;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * A fuzz run: inputs one after another through the {@link Sandbox}, counted per category; every failing
 * input written to the findings folder as a file that reproduces it ({@code --replay FILE}, or
 * {@code --seed S --from I --count 1}), with {@code findings.tsv} listing them.
 */
final class FuzzRun {
    /** What a run found. */
    record Result(Map<Outcome, Long> counts, List<Finding> findings, long inputs, double seconds, long atTick) {
        /** Failures (crash, hang, silent NaN, unlocated) blamed on one side. */
        long failures(String blame) {
            return findings.stream().filter(f -> blame == null || f.verdict().blame().equals(blame)).count();
        }
    }

    /** One failing input and where it was written. */
    record Finding(long index, Verdict verdict, Path file) {
    }

    /** Inputs between progress lines on stderr (a long run says it is alive). */
    private static final int PROGRESS = 10_000;

    private FuzzRun() {
    }

    static Result run(FuzzTarget target, FuzzOptions o, Path schema, Path out, PrintStream console)
            throws IOException, InterruptedException {
        Files.createDirectories(out);
        Map<Outcome, Long> counts = new EnumMap<>(Outcome.class);
        for (Outcome c : Outcome.values()) {
            counts.put(c, 0L);
        }
        List<Finding> findings = new ArrayList<>();
        long atTick = 0;
        long t0 = System.nanoTime();
        long n = o.replay != null ? o.replay.size() : o.count;
        try (Sandbox sandbox = new Sandbox(target.name(), schema, o.ticks, o.heap, Duration.ofSeconds(o.timeout),
                out.resolve("worker.log"))) {
            for (long k = 0; k < n; k++) {
                long index = o.from + k;
                byte[] input = o.replay != null ? Files.readAllBytes(o.replay.get((int) k)) : target.input(o.seed, index);
                Verdict v = sandbox.run(input);
                if ((k + 1) % PROGRESS == 0) {
                    System.err.printf(Locale.ROOT, "fuzz %s: %d of %d inputs, %d failing%n", target.name(), k + 1, n,
                            findings.size());
                }
                counts.merge(v.outcome(), 1L, Long::sum);
                atTick += v.outcome() == Outcome.CLEAN && v.stage().startsWith("tick") ? 1 : 0;
                if (v.outcome().failure()) {
                    Path file = out.resolve(String.format(Locale.ROOT, "s%d-i%d-%s.%s", o.seed, index,
                            v.outcome().name().toLowerCase(Locale.ROOT), target.extension()));
                    Files.write(file, input);
                    findings.add(new Finding(index, v, file));
                }
            }
        }
        Result r = new Result(counts, findings, n, (System.nanoTime() - t0) / 1e9, atTick);
        write(target, o, out, r);
        print(target, o, r, console);
        return r;
    }

    private static void write(FuzzTarget target, FuzzOptions o, Path out, Result r) throws IOException {
        StringBuilder tsv = new StringBuilder("index\toutcome\tblame\tstage\tmessage\tfile\treproduce\n");
        for (Finding f : r.findings()) {
            tsv.append(f.index()).append('\t').append(f.verdict().outcome().label()).append('\t')
                    .append(f.verdict().blame()).append('\t').append(f.verdict().stage()).append('\t')
                    .append(f.verdict().message()).append('\t').append(f.file().getFileName()).append('\t')
                    .append("./emini harness fuzz ").append(target.name()).append(" --replay ").append(f.file())
                    .append('\n');
        }
        Files.writeString(out.resolve("findings.tsv"), tsv, StandardCharsets.UTF_8);
    }

    private static void print(FuzzTarget target, FuzzOptions o, Result r, PrintStream console) {
        console.printf(Locale.ROOT, "fuzz %s: %d inputs in %.1f s (%.0f inputs/s), seed %d from %d%n", target.name(),
                r.inputs(), r.seconds(), r.inputs() / Math.max(r.seconds(), 1e-9), o.seed, o.from);
        for (Outcome c : Outcome.values()) {
            StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "  %-16s %d", c.label(), r.counts().get(c)));
            if (c == Outcome.CLEAN && r.atTick() > 0) {
                line.append("  (").append(r.atTick()).append(" by the engine's non-finite guard at tick)");
            }
            if (c.failure() && r.counts().get(c) > 0) {
                Map<String, Long> blame = new TreeMap<>();
                r.findings().stream().filter(f -> f.verdict().outcome() == c)
                        .forEach(f -> blame.merge(f.verdict().blame(), 1L, Long::sum));
                line.append("  (").append(blame.toString().replaceAll("[{}]", "")).append(')');
            }
            console.println(line);
        }
        // The distinct failures, each once with its first file: the list to fix.
        Map<String, Finding> distinct = new LinkedHashMap<>();
        for (Finding f : r.findings()) {
            distinct.putIfAbsent(f.verdict().outcome() + " " + f.verdict().message().replaceAll("\\d+", "#"), f);
        }
        distinct.values().stream().limit(20).forEach(f -> console.println("  " + f.verdict().outcome().label() + " ["
                + f.verdict().blame() + ", " + f.verdict().stage() + "] " + f.verdict().message() + "  -> " + f.file()));
        if (distinct.size() > 20) {
            console.println("  ... " + (distinct.size() - 20) + " more distinct failures in findings.tsv");
        }
    }
}
