package org.emini.harness.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.emini.harness.report.RunDiff;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code diff OLD NEW}: two runs' results compared (verdicts, errors against the truth, benchmark CPU
 * time, the run's own time per tick); exits 1 when NEW is worse than OLD beyond a tolerance. With
 * {@code --same-state}, the scenes' state hashes alone: exits 1 when a scene's state differs.
 */
@Command(name = "diff", mixinStandardHelpOptions = true,
        description = "Compares two runs (reports folders, or their results.json, compare.json or bench.json) and "
                + "fails on a regression beyond the tolerances: a scene that turned FAIL or ERROR, an error against "
                + "the truth that grew, a benchmark or run that got slower; with --same-state, a scene whose state "
                + "differs.")
final class DiffCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "OLD", description = "The earlier run: a reports folder or one of its files.")
    Path before;

    @Parameters(index = "1", paramLabel = "NEW", description = "The run to judge, the same way.")
    Path after;

    @Option(names = "--accuracy-tolerance", paramLabel = "R", defaultValue = "0.1",
            description = "An error against the truth (compare.json) may grow by this fraction (default: ${DEFAULT-VALUE}).")
    double accuracy;

    @Option(names = "--speed-tolerance", paramLabel = "R", defaultValue = "0.25",
            description = "A benchmark's CPU ms per tick (bench.json) may grow by this fraction (default: ${DEFAULT-VALUE}).")
    double speed;

    @Option(names = "--run-speed-tolerance", paramLabel = "R", defaultValue = "1",
            description = "A scene's wall µs per tick (results.json, noisy) may grow by this fraction (default: ${DEFAULT-VALUE}).")
    double runSpeed;

    @Option(names = "--run-millis", paramLabel = "MS", defaultValue = "200",
            description = "Scenes whose run took less (in either run) are not timed (default: ${DEFAULT-VALUE}).")
    double runMillis;

    @Option(names = "--same-state",
            description = "Compare only the scenes' state hashes (results.json, stateHash): every scene both runs ran "
                    + "to its end must have gone bit for bit the same way (a run at --workers 1 against one at 2, a build "
                    + "before an optimisation against one after).")
    boolean sameState;

    @Override
    public Integer call() throws Exception {
        for (double t : new double[] {accuracy, speed, runSpeed, runMillis}) {
            Options.require(spec, t >= 0 && Double.isFinite(t), "tolerances must be finite and >= 0, was " + t);
        }
        RunDiff.Result r = sameState ? RunDiff.sameState(before, after)
                : RunDiff.diff(before, after, new RunDiff.Tolerances(accuracy, speed, runSpeed, runMillis));
        List<RunDiff.Change> worse = r.regressions();
        for (String label : List.of("regressions", "improvements")) {
            List<RunDiff.Change> list = r.changes().stream().filter(c -> c.regression() == label.equals("regressions")).toList();
            if (list.isEmpty()) {
                continue;
            }
            System.out.println(label + ":");
            for (RunDiff.Change c : list) {
                System.out.println(String.format(Locale.ROOT, "  %-9s %-40s %s: %s -> %s", c.kind(), c.scene(), c.what(),
                        c.before(), c.after()));
            }
        }
        r.notes().forEach(n -> System.out.println("note: " + n));
        StringBuilder counts = new StringBuilder();
        r.compared().forEach((k, v) -> counts.append(counts.length() == 0 ? "" : ", ").append(v).append(' ').append(k));
        System.out.println("diff: compared " + (counts.length() == 0 ? "nothing" : counts) + "; " + worse.size()
                + " regressions, " + (r.changes().size() - worse.size()) + " improvements");
        if (r.compared().isEmpty()) {
            System.err.println("diff: OLD and NEW share no " + (sameState ? "scene with a state hash" : "results")
                    + " to compare");
            return ExitStatus.USAGE;
        }
        return worse.isEmpty() ? ExitStatus.OK : ExitStatus.FINDINGS;
    }
}
