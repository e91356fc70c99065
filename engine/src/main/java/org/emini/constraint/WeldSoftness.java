package org.emini.constraint;

/** A soft fixed joint's settings and, per tick, their soft-constraint coefficients (see SolverStep.soften). */
final class WeldSoftness {
    float linearHertz;
    float angularHertz;
    float dampingRatio;
    /** Bias rate, mass scale, impulse scale of the point and of the angle, for the tick's substep. */
    final float[] linear = new float[3];
    final float[] angular = new float[3];
}
