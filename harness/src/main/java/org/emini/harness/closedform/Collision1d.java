package org.emini.harness.closedform;

import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Channels;

/**
 * Models {@code collision1d}: body A left of body B on the x axis, no gravity, moving at constant
 * velocities until their extents touch at t_c = gap / (vA − vB), then
 * vA' = [(mA − e·mB)·vA + (1 + e)·mB·vB] / (mA + mB) and symmetrically for B. Predicts x and vx of
 * both, momentum.x (constant) and energy.kinetic (losing ½·μ·(1 − e²)·(vA − vB)² at impact).
 */
final class Collision1d implements ClosedForm {
    private final String a, b;
    private final double xa, xb, va, vb, ma, mb, vaAfter, vbAfter, tc;

    Collision1d(BodySpec bodyA, BodySpec bodyB, double e) {
        a = bodyA.name();
        b = bodyB.name();
        xa = bodyA.x();
        xb = bodyB.x();
        va = bodyA.state().vx();
        vb = bodyB.state().vx();
        ma = bodyA.shape().mass();
        mb = bodyB.shape().mass();
        double gap = (xb - xa) - (bodyA.shape().size()[0] + bodyB.shape().size()[0]) / 2;
        tc = va > vb ? gap / (va - vb) : Double.POSITIVE_INFINITY;
        vaAfter = ((ma - e * mb) * va + (1 + e) * mb * vb) / (ma + mb);
        vbAfter = ((mb - e * ma) * vb + (1 + e) * ma * va) / (ma + mb);
    }

    @Override
    public double predict(String channel, double t) {
        boolean after = t > tc;
        switch (channel) {
            case "momentum.x":
                return ma * va + mb * vb;
            case "energy.kinetic":
                return after ? 0.5 * (ma * vaAfter * vaAfter + mb * vbAfter * vbAfter) : 0.5 * (ma * va * va + mb * vb * vb);
            default:
                break;
        }
        String[] bc = Channels.bodyChannel(channel);
        if (bc == null || !(bc[0].equals(a) || bc[0].equals(b))) {
            return Double.NaN;
        }
        boolean isA = bc[0].equals(a);
        double x = isA ? xa : xb;
        double v = isA ? va : vb;
        double vAfter = isA ? vaAfter : vbAfter;
        switch (bc[1]) {
            case "x": return after ? x + v * tc + vAfter * (t - tc) : x + v * t;
            case "vx": return after ? vAfter : v;
            default: return Double.NaN;
        }
    }
}
