package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.List;
import org.emini.constraint.DistanceJoint;
import org.emini.constraint.Joint;
import org.emini.constraint.PrismaticJoint;
import org.emini.constraint.RevoluteJoint;
import org.emini.constraint.Spring;
import org.emini.constraint.TwoBodyConstraint;
import org.emini.constraint.WheelJoint;
import org.emini.dynamics.Constraint;
import org.emini.world.World;

/**
 * constraintError.max and .mean: over the constraints that hold a point or a length rigidly (px): the
 * distance between the two world anchors of each pin joint and revolute joint; B's anchor's distance
 * off the axis of each prismatic and wheel joint; |d − d₀| of each rigid link (a spring without
 * stiffness); how far a distance joint or rope lies outside its allowed lengths. Soft targets (motor
 * and mouse joints) have no error to measure.
 */
final class ConstraintErrorMetric implements Metric {
    private final List<Constraint> measured = new ArrayList<>();

    ConstraintErrorMetric(World world) {
        for (int i = 0; i < world.getConstraintCount(); i++) {
            Constraint c = world.getConstraint(i);
            if (c instanceof Joint || c instanceof RevoluteJoint || c instanceof PrismaticJoint || c instanceof WheelJoint
                || c instanceof DistanceJoint || (c instanceof Spring s && s.isRigid())) {
                measured.add(c);
            }
        }
    }

    @Override
    public List<String> channels() {
        return List.of("constraintError.max", "constraintError.mean");
    }

    private static double gap(TwoBodyConstraint c) {
        return Math.hypot(c.getAnchorBX() - c.getAnchorAX(), c.getAnchorBY() - c.getAnchorAY());
    }

    /** The anchors' separation less its component along the axis (the translation). */
    private static double offAxis(TwoBodyConstraint c, double translation) {
        double d = gap(c);
        return Math.sqrt(Math.max(0, d * d - translation * translation));
    }

    @Override
    public void sample(double[] out, int offset) {
        double max = 0;
        double sum = 0;
        for (Constraint c : measured) {
            double e;
            if (c instanceof Joint || c instanceof RevoluteJoint) {
                e = gap((TwoBodyConstraint) c);
            } else if (c instanceof PrismaticJoint p) {
                e = offAxis(p, p.getTranslation());
            } else if (c instanceof WheelJoint w) {
                e = offAxis(w, w.getTranslation());
            } else if (c instanceof DistanceJoint d) {
                double len = d.getCurrentLength();
                e = Math.max(0, Math.max(d.getMinLength() - len, len - d.getMaxLength()));
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
