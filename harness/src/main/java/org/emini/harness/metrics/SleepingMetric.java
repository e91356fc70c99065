package org.emini.harness.metrics;

import java.util.List;
import org.emini.dynamics.Body;
import org.emini.harness.build.BuiltWorld;

/**
 * sleeping.count = dynamic bodies asleep ({@code Body.isSleeping}); sleeping.fraction = that count over
 * the dynamic bodies (0 without any). Both stay 0 in a world that does not let bodies sleep.
 */
final class SleepingMetric implements Metric {
    private final Body[] bodies;

    SleepingMetric(BuiltWorld built) {
        bodies = DynamicBodies.of(built);
    }

    @Override
    public List<String> channels() {
        return List.of("sleeping.count", "sleeping.fraction");
    }

    @Override
    public void sample(double[] out, int offset) {
        int asleep = 0;
        for (Body b : bodies) {
            if (b.isSleeping()) {
                asleep++;
            }
        }
        out[offset] = asleep;
        out[offset + 1] = bodies.length == 0 ? 0 : asleep / (double) bodies.length;
    }
}
