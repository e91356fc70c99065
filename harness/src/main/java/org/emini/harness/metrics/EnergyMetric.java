package org.emini.harness.metrics;

import java.util.List;
import org.emini.constraint.Spring;
import org.emini.dynamics.Body;
import org.emini.world.World;
import org.emini.harness.build.BuiltWorld;

/**
 * energy.kinetic = Σ ½·m·|v|² + ½·I·ω² over dynamic bodies; energy.potential = Σ −m·(g·r) over dynamic,
 * gravity-affected bodies (r the body position, which is its centre of mass; g the current gravity);
 * energy.total = their sum plus the springs' potential Σ ½·k·(d − d₀)² (springs with a stiffness).
 */
final class EnergyMetric implements Metric {
    private final World world;
    private final Body[] bodies;

    EnergyMetric(BuiltWorld built) {
        world = built.world();
        bodies = DynamicBodies.of(built);
    }

    @Override
    public List<String> channels() {
        return List.of("energy.kinetic", "energy.potential", "energy.total");
    }

    @Override
    public void sample(double[] out, int offset) {
        double gx = world.getGravityX();
        double gy = world.getGravityY();
        double kinetic = 0;
        double potential = 0;
        for (Body b : bodies) {
            double m = b.getMass();
            double vx = b.getVelocityX();
            double vy = b.getVelocityY();
            kinetic += 0.5 * m * (vx * vx + vy * vy) + DynamicBodies.rotationalEnergy(b);
            if (b.isAffectedByGravity()) {
                potential -= m * (gx * b.getX() + gy * b.getY());
            }
        }
        double springs = 0;
        for (int i = 0; i < world.getConstraintCount(); i++) {
            if (world.getConstraint(i) instanceof Spring s && !s.isRigid()) {
                double stretch = s.getLength() - s.getRestLength();
                springs += 0.5 * s.getCoefficient() * stretch * stretch;
            }
        }
        out[offset] = kinetic;
        out[offset + 1] = potential;
        out[offset + 2] = kinetic + potential + springs;
    }
}
