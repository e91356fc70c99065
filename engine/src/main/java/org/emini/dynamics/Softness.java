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

    /**
     * Sets the coefficients.
     *
     * @param hertz the stiffness as a natural frequency (Hz); 0 means rigid with no position bias
     * @param dampingRatio the damping ratio (1 = critical)
     * @param h the substep (s)
     */
    Softness set(float hertz, float dampingRatio, float h) {
        if (hertz == 0f) {
            biasRate = 0f;
            massScale = 1f;
            impulseScale = 0f;
            return this;
        }
        float omega = EMath.TWO_PI * hertz;
        float a1 = 2f * dampingRatio + h * omega;
        float a2 = h * omega * a1;
        float a3 = 1f / (1f + a2);
        biasRate = omega / a1;
        massScale = a2 * a3;
        impulseScale = a3;
        return this;
    }
}
