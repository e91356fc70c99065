package org.emini.harness.closedform;

import org.emini.harness.scenario.BodySpec;
import org.emini.harness.scenario.Channels;

/**
 * Models {@code projectile} and {@code freeRotation}: a body under constant gravity g with no contact,
 * r(t) = r0 + v0·t + ½·g·t², v(t) = v0 + g·t, angle(t) = angle0 + ω0·t, ω constant.
 * (Symplectic Euler gets v exact and r wrong by ½·g·h·t: tolerances must allow for that.)
 */
final class Ballistic implements ClosedForm {
    private final String body;
    private final double x0, y0, vx0, vy0, a0, w0, gx, gy;

    Ballistic(BodySpec b, double gx, double gy) {
        body = b.name();
        x0 = b.x();
        y0 = b.y();
        vx0 = b.state().vx();
        vy0 = b.state().vy();
        a0 = b.state().angle();
        w0 = b.state().rotatable() ? b.state().angularVelocity() : 0;
        this.gx = b.state().gravity() ? gx : 0;
        this.gy = b.state().gravity() ? gy : 0;
    }

    @Override
    public double predict(String channel, double t) {
        String[] bc = Channels.bodyChannel(channel);
        if (bc == null || !bc[0].equals(body)) {
            return Double.NaN;
        }
        switch (bc[1]) {
            case "x": return x0 + vx0 * t + 0.5 * gx * t * t;
            case "y": return y0 + vy0 * t + 0.5 * gy * t * t;
            case "vx": return vx0 + gx * t;
            case "vy": return vy0 + gy * t;
            case "speed": return Math.hypot(vx0 + gx * t, vy0 + gy * t);
            case "angle": return a0 + w0 * t;
            case "omega": return w0;
            default: return Double.NaN;
        }
    }
}
