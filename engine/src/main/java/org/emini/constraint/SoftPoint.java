package org.emini.constraint;

import org.emini.math.EMath;

/**
 * A soft point row with a capped force, for the joints that pull a point toward a goal (mouse and
 * motor joints): a spring-damper of given frequency solved implicitly over the substep
 * (SolverStep.soften), its accumulated impulse clamped in magnitude to the cap times the substep.
 * The caller computes the geometry and applies {@link #dx}, {@link #dy} after each solve.
 *
 * <p>The spring's pull speed (bias rate times distance) is capped at {@link #brakingSpeed}: the
 * fastest the capped force can still stop from before the goal. Uncapped, a spring stiff enough to
 * saturate the cap drives the point at full force until just before the goal and overshoots by
 * about the distance it ran (Box2D's mouse joint with a low force circles its target this way: in
 * a model of ours a 400 px drag at 5 Hz overshot by 350 px and kept circling).
 */
final class SoftPoint {
    /** Bias rate, mass scale, impulse scale for the tick's substep. */
    final float[] soft = new float[3];
    private float accX;
    private float accY;
    private float warmX;
    private float warmY;
    private float tickX;
    private float tickY;
    private float k11;
    private float k12;
    private float k22;
    /** The impulse the last {@link #solve} added. */
    float dx;
    float dy;

    void beginTick() {
        tickX = 0f;
        tickY = 0f;
    }

    /** Scales the stored impulse to the substep; the caller applies {@link #impulseX()}, {@link #impulseY()}. */
    void warmStart(float substepScale) {
        accX *= substepScale;
        accY *= substepScale;
        warmX = accX;
        warmY = accY;
        tickX += accX;
        tickY += accY;
    }

    float impulseX() {
        return accX;
    }

    float impulseY() {
        return accY;
    }

    /**
     * One solve.
     *
     * @param cx x of the velocity error (px/s)
     * @param cy y of the velocity error (px/s)
     * @param ex x of the position error, the point minus its goal (px)
     * @param ey y of the position error (px)
     * @param m11 K = J·M⁻¹·Jᵀ, xx
     * @param m12 K, xy
     * @param m22 K, yy
     * @param cap the largest impulse of a substep (mass·px/s)
     * @param maxAcceleration what the cap gives the point at least, the force cap times the
     *     inverse masses (px/s²)
     */
    void solve(float cx, float cy, float ex, float ey, float m11, float m12, float m22, float cap,
            float maxAcceleration) {
        k11 = m11;
        k12 = m12;
        k22 = m22;
        float det = m11 * m22 - m12 * m12;
        if (!(det > 0f)) {
            dx = 0f;
            dy = 0f;
            return;
        }
        float pullX = soft[0] * ex;
        float pullY = soft[0] * ey;
        float pull = EMath.length(pullX, pullY);
        float max = brakingSpeed(maxAcceleration, EMath.length(ex, ey));
        if (pull > max) {
            pullX *= max / pull;
            pullY *= max / pull;
        }
        float bx = cx + pullX;
        float by = cy + pullY;
        float inv = soft[1] / det;
        float oldX = accX;
        float oldY = accY;
        accX += -inv * (m22 * bx - m12 * by) - soft[2] * oldX;
        accY += -inv * (m11 * by - m12 * bx) - soft[2] * oldY;
        float len = EMath.length(accX, accY);
        if (len > cap) {
            float s = cap / len;
            accX *= s;
            accY *= s;
        }
        dx = accX - oldX;
        dy = accY - oldY;
        tickX += dx;
        tickY += dy;
    }

    /**
     * The speed from which a body braking at 90% of a given acceleration stops within a distance:
     * √(2·0.9·a·d). The 10% margin covers the spring's lag behind the braking curve (without it a
     * capped 400 px drag overshot by 2.4 px; with it by 0.06 px).
     *
     * @param acceleration a (px/s², or rad/s²), infinite for no cap
     * @param distance d (px, or rad)
     * @return the speed (px/s, or rad/s)
     */
    static float brakingSpeed(float acceleration, float distance) {
        return EMath.sqrt(1.8f * acceleration * distance);
    }

    /** The relax pass's report: the velocity change of the substep's impulse beyond its warm start. */
    float change() {
        float jx = accX - warmX;
        float jy = accY - warmY;
        return Math.max(Math.abs(k11 * jx + k12 * jy), Math.abs(k12 * jx + k22 * jy));
    }

    /** The tick's force magnitude. */
    float force(float timestep) {
        return EMath.length(tickX, tickY) / timestep;
    }
}
