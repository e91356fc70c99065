package org.emini.harness.fuzz;

import java.util.List;
import picocli.CommandLine.Command;

/** {@code fuzz setters}: the engine's public setters and constructors with extreme values, then a few ticks. */
@Command(name = "setters", mixinStandardHelpOptions = true,
        description = "Calls the engine's public setters, factories and constructors (found by reflection) on a small "
                + "world with NaN, infinities, ±1e30, ±3.4e38, 1.4e-45, 0, negatives and integer limits, then ticks it.")
final class SettersFuzzCommand extends FuzzSubcommand {
    @Override
    FuzzTarget target() {
        return new FuzzTarget("setters", "txt", List.of());
    }
}
