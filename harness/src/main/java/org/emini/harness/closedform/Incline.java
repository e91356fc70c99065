package org.emini.harness.closedform;

import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Channels;

/**
 * Models {@code incline} (a block) and {@code rollingDisc}, both starting at rest on a plane at angle θ
 * to the horizontal under gravity g (straight down the screen). Distance down the slope s(t) = ½·a·t²:
 * a block sticks if tan|θ| ≤ μ, else a = g·(sin|θ| − μ·cos|θ|); a uniform disc rolling without
 * slipping has a = ⅔·g·sin|θ| and ω = ṡ / r (positive, clockwise on screen, when it rolls toward +x).
 * The slope descends toward +x for θ &gt; 0.
 */
final class Incline implements ClosedForm {
    private final String body;
    private final double x0, y0, a0, dx, dy, accel, radius, spin;

    Incline(BodySpec b, double g, double slopeDeg, double friction, double radius, boolean rolling) {
        body = b.name();
        x0 = b.x();
        y0 = b.y();
        a0 = b.state().angle();
        double theta = Math.toRadians(Math.abs(slopeDeg));
        double side = Math.signum(slopeDeg);
        dx = side * Math.cos(theta);
        dy = Math.sin(theta);
        if (rolling) {
            accel = 2.0 / 3.0 * g * Math.sin(theta);
        } else {
            accel = Math.tan(theta) <= friction ? 0 : g * (Math.sin(theta) - friction * Math.cos(theta));
        }
        this.radius = radius;
        spin = rolling ? side : 0;
    }

    @Override
    public double predict(String channel, double t) {
        String[] bc = Channels.bodyChannel(channel);
        if (bc == null || !bc[0].equals(body)) {
            return Double.NaN;
        }
        double s = 0.5 * accel * t * t;
        double v = accel * t;
        switch (bc[1]) {
            case "x": return x0 + s * dx;
            case "y": return y0 + s * dy;
            case "vx": return v * dx;
            case "vy": return v * dy;
            case "speed": return v;
            case "angle": return spin == 0 ? Double.NaN : a0 + spin * s / radius;
            case "omega": return spin == 0 ? Double.NaN : spin * v / radius;
            default: return Double.NaN;
        }
    }
}
