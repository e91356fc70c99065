package org.emini.harness.closedform;

import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Channels;

/**
 * Models {@code pendulum}: a rigid body pinned at a pivot, swinging under gravity g. With φ the angle of
 * (r − pivot) and d its length, I_p·φ̈ = m·(d·cos φ·gy − d·sin φ·gx), I_p = I + m·d². There is no
 * elementary closed form at large amplitude (the period is 4·√(L/g)·K(sin²(θ0/2)), L = I_p/(m·d)),
 * so the motion is integrated with classical RK4 at a step far below the engine's (1e-4 s), which is
 * exact to well below any tolerance used here. Predicts x, y, angle, omega of the body.
 */
final class Pendulum implements ClosedForm {
    private static final double STEP = 1e-4;

    private final String body;
    private final double px, py, d, a0, phi0;
    private final double[] phi;
    private final double[] omega;

    Pendulum(BodySpec b, double inertia, double pivotX, double pivotY, double gx, double gy, double duration) {
        body = b.name();
        px = pivotX;
        py = pivotY;
        double rx = b.x() - px;
        double ry = b.y() - py;
        d = Math.hypot(rx, ry);
        double m = b.shape().mass();
        double ip = inertia + m * d * d;
        a0 = b.state().angle();
        phi0 = Math.atan2(ry, rx);
        // Initial swing rate from the body's velocity perpendicular to the arm.
        double w0 = d == 0 ? 0 : (rx * b.state().vy() - ry * b.state().vx()) / (d * d);
        int n = (int) Math.ceil(duration / STEP) + 2;
        phi = new double[n];
        omega = new double[n];
        phi[0] = phi0;
        omega[0] = w0;
        double k = m * d / ip;
        for (int i = 1; i < n; i++) {
            double p = phi[i - 1];
            double w = omega[i - 1];
            double k1p = w, k1w = k * (Math.cos(p) * gy - Math.sin(p) * gx);
            double p2 = p + 0.5 * STEP * k1p, w2 = w + 0.5 * STEP * k1w;
            double k2p = w2, k2w = k * (Math.cos(p2) * gy - Math.sin(p2) * gx);
            double p3 = p + 0.5 * STEP * k2p, w3 = w + 0.5 * STEP * k2w;
            double k3p = w3, k3w = k * (Math.cos(p3) * gy - Math.sin(p3) * gx);
            double p4 = p + STEP * k3p, w4 = w + STEP * k3w;
            double k4p = w4, k4w = k * (Math.cos(p4) * gy - Math.sin(p4) * gx);
            phi[i] = p + STEP / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
            omega[i] = w + STEP / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
        }
    }

    private double at(double[] series, double t) {
        double i = t / STEP;
        int lo = (int) Math.min(Math.floor(i), series.length - 2);
        double f = i - lo;
        return series[lo] * (1 - f) + series[lo + 1] * f;
    }

    @Override
    public double predict(String channel, double t) {
        String[] bc = Channels.bodyChannel(channel);
        if (bc == null || !bc[0].equals(body)) {
            return Double.NaN;
        }
        double p = at(phi, t);
        switch (bc[1]) {
            case "x": return px + d * Math.cos(p);
            case "y": return py + d * Math.sin(p);
            case "angle": return a0 + (p - phi0);
            case "omega": return at(omega, t);
            default: return Double.NaN;
        }
    }
}
