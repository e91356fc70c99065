package org.emini.harness.closedform;

import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Channels;

/**
 * Models {@code dampedSpring}: a body on a spring (stiffness k, damping c, rest length L0) to a fixed
 * anchor, moving along the anchor–body line u under gravity g. The length obeys
 * m·ℓ̈ = −k·(ℓ − L0) − c·ℓ̇ + m·(g·u); with x = ℓ − ℓe, ℓe = L0 + m·(g·u)/k, ω = √(k/m),
 * ζ = c/(2√(km)): x(t) = e^(−ζωt)·[x0·cos(ωd·t) + (v0 + ζω·x0)/ωd·sin(ωd·t)], ωd = ω·√(1 − ζ²)
 * (and the critically and over-damped forms). Predicts x, y, vx, vy of the body.
 */
final class DampedSpring implements ClosedForm {
    private final String body;
    private final double ax, ay, ux, uy, le, x0, v0, w, zeta;

    DampedSpring(BodySpec b, double anchorX, double anchorY, double k, double c, double restLength,
                 double gx, double gy) {
        body = b.name();
        ax = anchorX;
        ay = anchorY;
        double rx = b.x() - ax;
        double ry = b.y() - ay;
        double len = Math.hypot(rx, ry);
        ux = rx / len;
        uy = ry / len;
        double m = b.shape().mass();
        le = restLength + m * (gx * ux + gy * uy) / k;
        x0 = len - le;
        v0 = b.state().vx() * ux + b.state().vy() * uy;
        w = Math.sqrt(k / m);
        zeta = c / (2 * Math.sqrt(k * m));
    }

    /** {x(t), ẋ(t)}. */
    private double[] state(double t) {
        double x;
        double v;
        if (zeta < 1) {
            double wd = w * Math.sqrt(1 - zeta * zeta);
            double a = x0;
            double bb = (v0 + zeta * w * x0) / wd;
            double e = Math.exp(-zeta * w * t);
            double cos = Math.cos(wd * t);
            double sin = Math.sin(wd * t);
            x = e * (a * cos + bb * sin);
            v = -zeta * w * x + e * (-a * wd * sin + bb * wd * cos);
        } else if (zeta == 1) {
            double bb = v0 + w * x0;
            double e = Math.exp(-w * t);
            x = (x0 + bb * t) * e;
            v = bb * e - w * x;
        } else {
            double s = w * Math.sqrt(zeta * zeta - 1);
            double r1 = -zeta * w + s;
            double r2 = -zeta * w - s;
            double c2 = (v0 - r1 * x0) / (r2 - r1);
            double c1 = x0 - c2;
            x = c1 * Math.exp(r1 * t) + c2 * Math.exp(r2 * t);
            v = c1 * r1 * Math.exp(r1 * t) + c2 * r2 * Math.exp(r2 * t);
        }
        return new double[] {x, v};
    }

    @Override
    public double predict(String channel, double t) {
        String[] bc = Channels.bodyChannel(channel);
        if (bc == null || !bc[0].equals(body)) {
            return Double.NaN;
        }
        double[] s = state(t);
        double len = le + s[0];
        switch (bc[1]) {
            case "x": return ax + len * ux;
            case "y": return ay + len * uy;
            case "vx": return s[1] * ux;
            case "vy": return s[1] * uy;
            default: return Double.NaN;
        }
    }
}
