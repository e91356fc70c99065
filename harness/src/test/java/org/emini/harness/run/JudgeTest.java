package org.emini.harness.run;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.emini.harness.expect.Verdict;
import org.emini.harness.scenario.KnownFailure;
import org.junit.jupiter.api.Test;

/** The known-failure rules: only an unmarked failing expectation fails the run. */
class JudgeTest {
    private static final KnownFailure MARK = new KnownFailure("sinks", "3.2", null);

    private static Verdict ok(KnownFailure k) {
        return new Verdict("ok", true, 1, "fine", k);
    }

    private static Verdict bad(KnownFailure k) {
        return new Verdict("bad", false, 5, "too much", k);
    }

    private static Status judge(KnownFailure scene, List<String> stale, Verdict... verdicts) {
        return Judge.judge(List.of(verdicts), scene, stale, new StringBuilder());
    }

    @Test
    void passingScenePasses() {
        assertEquals(Status.PASS, judge(null, new ArrayList<>(), ok(null), ok(null)));
    }

    @Test
    void unmarkedFailureIsARegression() {
        assertEquals(Status.FAIL, judge(null, new ArrayList<>(), ok(null), bad(null)));
        assertEquals(Status.FAIL, judge(null, new ArrayList<>(), bad(MARK), bad(null)));
        assertEquals(true, Status.FAIL.failsRun());
    }

    @Test
    void markedFailureIsKnownAndDoesNotFailTheRun() {
        assertEquals(Status.KNOWN_FAILURE, judge(null, new ArrayList<>(), ok(null), bad(MARK)));
        assertEquals(Status.KNOWN_FAILURE, judge(MARK, new ArrayList<>(), bad(null)));
        assertEquals(false, Status.KNOWN_FAILURE.failsRun());
    }

    @Test
    void aMarkThatNowPassesIsReportedButPasses() {
        List<String> stale = new ArrayList<>();
        assertEquals(Status.PASS, judge(null, stale, ok(MARK)));
        assertEquals(List.of("ok"), stale);
    }
}
