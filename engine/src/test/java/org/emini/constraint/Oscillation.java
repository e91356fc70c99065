package org.emini.constraint;

import java.util.function.DoubleSupplier;
import org.emini.world.World;

/** Measures the period of an oscillating reading from its upward crossings of its known centre. */
final class Oscillation {
    private Oscillation() {
    }

    /** Ticks until the reading has crossed the centre upward periods + 1 times; the mean time between crossings. */
    static double period(World world, DoubleSupplier reading, double centre, int periods) {
        double dt = world.getTimestep();
        double previous = reading.getAsDouble();
        double first = -1.0;
        double last = -1.0;
        int crossings = 0;
        int limit = (int) Math.ceil(60.0 / dt);
        for (int i = 0; i < limit && crossings <= periods; i++) {
            world.tick();
            double value = reading.getAsDouble();
            if (previous < centre && value >= centre) {
                last = (i + (centre - previous) / (value - previous)) * dt;
                if (first < 0.0) {
                    first = last;
                }
                crossings++;
            }
            previous = value;
        }
        if (crossings <= periods) {
            throw new AssertionError("only " + crossings + " upward crossings of " + centre + " in 60 s");
        }
        return (last - first) / periods;
    }
}
