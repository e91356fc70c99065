package org.emini.harness.expect;

import org.emini.harness.scenario.KnownFailure;

/**
 * The outcome of one expectation.
 *
 * @param expectation what was expected (the scene's name for it or a generated description)
 * @param passed whether it holds
 * @param measured the figure it was judged on (NaN when there was none)
 * @param detail a sentence with the figure and the bound
 * @param knownFailure the expectation's known-failure mark, or null
 */
public record Verdict(String expectation, boolean passed, double measured, String detail, KnownFailure knownFailure) {
}
