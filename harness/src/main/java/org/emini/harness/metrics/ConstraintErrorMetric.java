package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.List;
import org.emini.constraint.Joint;
import org.emini.constraint.Spring;
import org.emini.dynamics.Constraint;
import org.emini.world.World;

/**
 * constraintError.max and .mean: the distance between the two world anchors of each pin joint and
 * |d − d₀| of each rigid link (a spring without stiffness), over those constraints (px).
 */
final class ConstraintErrorMetric implements Metric {
    private final List<Constraint> measured = new ArrayList<>();

    ConstraintErrorMetric(World world) {
        for (int i = 0; i < world.getConstraintCount(); i++) {
            Constraint c = world.getConstraint(i);
            if (c instanceof Joint || (c instanceof Spring s && s.isRigid())) {
                measured.add(c);
            }
        }
    }

    @Override
    public List<String> channels() {
        return List.of("constraintError.max", "constraintError.mean");
    }

    @Override
    public void sample(double[] out, int offset) {
        double max = 0;
        double sum = 0;
        for (Constraint c : measured) {
            double e;
            if (c instanceof Joint j) {
                e = Math.hypot(j.getAnchorBX() - j.getAnchorAX(), j.getAnchorBY() - j.getAnchorAY());
            } else {
                Spring s = (Spring) c;
                e = Math.abs(s.getLength() - s.getRestLength());
            }
            max = Math.max(max, e);
            sum += e;
        }
        out[offset] = max;
        out[offset + 1] = measured.isEmpty() ? 0 : sum / measured.size();
    }
}
