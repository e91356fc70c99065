package org.emini.harness.run;

import java.util.ArrayList;
import java.util.List;
import org.emini.harness.expect.Verdict;
import org.emini.harness.scenario.KnownFailure;

/**
 * Turns a scene's verdicts into its status. A failing expectation fails the run unless it (or the
 * whole scene) is marked as a known failure; a marked expectation that now passes is reported so the
 * mark can be removed, but does not fail the run.
 */
public final class Judge {
    private Judge() {
    }

    /**
     * The status and message.
     *
     * @param verdicts the expectations' verdicts
     * @param sceneMark the scene-level known-failure mark, or null
     * @param stale filled with the expectations marked known that passed
     */
    public static Status judge(List<Verdict> verdicts, KnownFailure sceneMark, List<String> stale, StringBuilder message) {
        List<Verdict> regressions = new ArrayList<>();
        List<Verdict> known = new ArrayList<>();
        for (Verdict v : verdicts) {
            if (v.passed()) {
                if (v.knownFailure() != null) {
                    stale.add(v.expectation());
                }
            } else if (v.knownFailure() != null || sceneMark != null) {
                known.add(v);
            } else {
                regressions.add(v);
            }
        }
        if (!regressions.isEmpty()) {
            Verdict first = regressions.get(0);
            message.append(first.expectation()).append(": ").append(first.detail());
            if (regressions.size() > 1) {
                message.append(" (and ").append(regressions.size() - 1).append(" more)");
            }
            return Status.FAIL;
        }
        if (!known.isEmpty()) {
            Verdict first = known.get(0);
            KnownFailure mark = first.knownFailure() != null ? first.knownFailure() : sceneMark;
            message.append(first.expectation()).append(": ").append(first.detail()).append(" [known: ")
                    .append(mark.reason()).append("; marked at ").append(mark.measured()).append(']');
            return Status.KNOWN_FAILURE;
        }
        if (!stale.isEmpty()) {
            message.append("known failure now passes, remove its mark: ").append(String.join("; ", stale));
        } else if (sceneMark != null) {
            message.append("scene marked as a known failure now passes: remove the mark");
            stale.add("(scene)");
        }
        return Status.PASS;
    }
}
