package org.emini.dynamics;

/**
 * What every contact pass of a substep needs beyond the bodies, set once per tick by the
 * {@link Solver} (the horizon once per substep): one object instead of a long parameter list.
 */
final class SubstepContext {
    /** 1 / substep length (1/s). */
    float invH;
    /** Cap on the push-out speed (px/s). */
    float maxPush;
    /** Penetration left alone so resting contacts do not jitter (px). */
    float slop;
    /** A relax pass marks for the hot passes the bodies it changed by more than this (px/s). */
    float hotTolerance;
    /** The most hot passes after a substep's first relax pass. */
    int maxHotPasses;
    /**
     * Dynamic iterations: the time left in the tick after this substep (s), over which the relax
     * pass measures whether the solve may stop; negative when nothing is measured.
     */
    float horizon = -1f;
    /** Gravity (px/s²): it may close a gap to a static body within the horizon. */
    float gravityX;
    /** Gravity (px/s²). */
    float gravityY;
}
