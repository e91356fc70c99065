package org.emini.harness.scenario;

import java.util.List;

/**
 * The run: how long, what to record, what must come out.
 *
 * @param duration simulated seconds (rounded up to whole ticks)
 * @param record sampling and metrics
 * @param expect the expectations, in file order
 */
public record RunSpec(double duration, RecordSpec record, List<ExpectationSpec> expect) {
}
