package org.emini.harness.metrics;

import java.util.ArrayList;
import java.util.List;
import org.emini.constraint.PrismaticJoint;
import org.emini.constraint.RevoluteJoint;
import org.emini.dynamics.Constraint;
import org.emini.world.World;

/**
 * jointLimits.angle and .translation: how far the worst limited joint lies outside its limits now:
 * revolute joints' angle (rad) and prismatic joints' translation (px); 0 when all are within them.
 * (A wheel joint's travel limits have no getters in the engine, so they are not measured.)
 */
final class JointLimitsMetric implements Metric {
    private final List<RevoluteJoint> hinges = new ArrayList<>();
    private final List<PrismaticJoint> slides = new ArrayList<>();

    JointLimitsMetric(World world) {
        for (int i = 0; i < world.getConstraintCount(); i++) {
            Constraint c = world.getConstraint(i);
            if (c instanceof RevoluteJoint r && r.isLimitEnabled()) {
                hinges.add(r);
            } else if (c instanceof PrismaticJoint p && p.isLimitEnabled()) {
                slides.add(p);
            }
        }
    }

    @Override
    public List<String> channels() {
        return List.of("jointLimits.angle", "jointLimits.translation");
    }

    private static double outside(double v, double lower, double upper) {
        return Math.max(0, Math.max(lower - v, v - upper));
    }

    @Override
    public void sample(double[] out, int offset) {
        double angle = 0;
        for (RevoluteJoint r : hinges) {
            angle = Math.max(angle, outside(r.getJointAngle(), r.getLowerLimit(), r.getUpperLimit()));
        }
        double translation = 0;
        for (PrismaticJoint p : slides) {
            translation = Math.max(translation, outside(p.getTranslation(), p.getLowerLimit(), p.getUpperLimit()));
        }
        out[offset] = angle;
        out[offset + 1] = translation;
    }
}
