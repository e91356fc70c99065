package org.emini.dynamics;

import org.emini.math.EMath;

/**
 * Soft-constraint coefficients for a spring-damper of given frequency and damping ratio, integrated
 * implicitly over a substep h (Catto, "Solver2D", 2024). A soft constraint stays stable whatever
 * the product of its frequency and the timestep.
 */
final class Softness {
    /** Position error to velocity (1/s). */
    float biasRate;
    /** Fraction of the effective mass used. */
    float massScale = 1f;
    /** Fraction of the accumulated impulse relaxed away each solve. */
    float impulseScale;
    private final float[] scratch = new float[3];

    /**
     * Sets the coefficients.
     *
     * @param hertz the stiffness as a natural frequency (Hz); 0 means rigid with no position bias
     * @param dampingRatio the damping ratio (1 = critical)
     * @param h the substep (s)
     */
    Softness set(float hertz, float dampingRatio, float h) {
        coefficients(hertz, dampingRatio, h, scratch);
        biasRate = scratch[0];
        massScale = scratch[1];
        impulseScale = scratch[2];
        return this;
    }

    /** The same coefficients into an array: bias rate, mass scale, impulse scale. */
    static void coefficients(float hertz, float dampingRatio, float h, float[] out) {
        if (hertz == 0f) {
            out[0] = 0f;
            out[1] = 1f;
            out[2] = 0f;
            return;
        }
        float omega = EMath.TWO_PI * hertz;
        float a1 = 2f * dampingRatio + h * omega;
        float a2 = h * omega * a1;
        float a3 = 1f / (1f + a2);
        out[0] = omega / a1;
        out[1] = a2 * a3;
        out[2] = a3;
    }
}
