package org.emini.dynamics;

import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * Tuning of the contact solver and collision margins. Every value has a unit and a stated origin.
 *
 * <p>Lengths are in pixels. The defaults assume bodies of roughly 10 to 100 px, as in the original
 * engine's worlds (its boxes are usually 20 px); the Box2D v3 defaults they derive from are given in
 * metres, converted at 20 px per metre. For worlds of much smaller or larger bodies, set the
 * {@linkplain #setLengthScale length scale} rather than each tolerance.
 */
public final class SolverSettings {
    /** Default of {@link #getMaxContacts()}: 2²⁰. */
    public static final int DEFAULT_MAX_CONTACTS = 1 << 20;

    private float linearSlop = 0.05f;
    private float speculativeDistance = 0.5f;
    private float speculativeSweep = 1f;
    private float manifoldReuseDistance = 0.1f;
    private float aabbMargin = 2f;
    private float contactHertz = 240f;
    private float contactDampingRatio = 10f;
    private float contactPushMaxVelocity = 60f;
    private float jointPushMaxVelocity = 1000f;
    private float restitutionThreshold = 10f;
    private float convergenceTolerance = 0.02f;
    private float impactTolerance = 5f;
    private int impactRelaxPasses = 100;
    private float sinkLimit = 0.5f;
    private float sinkSubstepFactor = 2f;
    private float timeOfImpactTarget = 0.25f;
    private float substepHertzRatio = 0.25f;
    private float blockConditionLimit = 1000f;
    private float jointHertz = 60f;
    private float jointDampingRatio = 2f;
    private int maxContacts = DEFAULT_MAX_CONTACTS;
    private float sleepLinearTolerance = 1f;
    private float sleepAngularTolerance = 2f * EMath.PI / 180f;
    private float timeToSleep = 0.5f;
    private float lengthScale = 1f;

    /** Creates the default settings. */
    public SolverSettings() {
    }

    /**
     * Makes these settings a copy of another's, every value as it is there (the length scale is
     * copied, not applied again).
     *
     * @param other the settings to copy
     */
    public void set(SolverSettings other) {
        linearSlop = other.linearSlop;
        speculativeDistance = other.speculativeDistance;
        speculativeSweep = other.speculativeSweep;
        manifoldReuseDistance = other.manifoldReuseDistance;
        aabbMargin = other.aabbMargin;
        contactHertz = other.contactHertz;
        contactDampingRatio = other.contactDampingRatio;
        contactPushMaxVelocity = other.contactPushMaxVelocity;
        jointPushMaxVelocity = other.jointPushMaxVelocity;
        restitutionThreshold = other.restitutionThreshold;
        convergenceTolerance = other.convergenceTolerance;
        impactTolerance = other.impactTolerance;
        impactRelaxPasses = other.impactRelaxPasses;
        sinkLimit = other.sinkLimit;
        sinkSubstepFactor = other.sinkSubstepFactor;
        timeOfImpactTarget = other.timeOfImpactTarget;
        substepHertzRatio = other.substepHertzRatio;
        blockConditionLimit = other.blockConditionLimit;
        jointHertz = other.jointHertz;
        jointDampingRatio = other.jointDampingRatio;
        maxContacts = other.maxContacts;
        sleepLinearTolerance = other.sleepLinearTolerance;
        sleepAngularTolerance = other.sleepAngularTolerance;
        timeToSleep = other.timeToSleep;
        lengthScale = other.lengthScale;
    }

    /**
     * Overlap the solver leaves alone so resting contacts do not jitter. Default 0.05 px (the
     * original engine allowed 1/16 px; Box2D v3 0.005 m).
     *
     * @return the slop (px)
     */
    public float getLinearSlop() {
        return linearSlop;
    }

    /**
     * Sets the slop.
     *
     * @param px the slop (px), ≥ 0
     */
    public void setLinearSlop(float px) {
        linearSlop = Check.nonNegative("SolverSettings.setLinearSlop", "px", px);
    }

    /**
     * Gap below which contact points are created before the shapes touch, on top of the distance
     * the bodies can close in one tick ({@linkplain #getSpeculativeSweep the sweep}). Default 0.5 px.
     *
     * @return the distance (px)
     */
    public float getSpeculativeDistance() {
        return speculativeDistance;
    }

    /**
     * Sets the speculative distance.
     *
     * @param px the distance (px), ≥ 0
     */
    public void setSpeculativeDistance(float px) {
        speculativeDistance = Check.nonNegative("SolverSettings.setSpeculativeDistance", "px", px);
    }

    /**
     * How much of the distance a pair can close in one tick widens its speculative distance: 1 (the
     * default) covers every gap that the two bodies' speeds at the start of the tick could close,
     * whichever way they move, so a body that stops mid-tick (a landing column, a falling crowd) does
     * not run into the one behind it; 0 keeps the speculative distance alone, Box2D v3's choice.
     *
     * <p>Below 1 fewer contacts are solved where many bodies move fast (a tumbling pile: at 0 it runs in
     * about 0.77 of its time), and contacts come later: falling bodies overlap, landings rebound, and
     * two fast dynamic bodies may pass through each other (the fast-body pass still sweeps fast bodies
     * against static and moving kinematic ones, and bullets against every body). At 0, 7 of the
     * scenario library's 99 scenes fail (bench/RESULTS.md, session 22).
     *
     * @return the factor
     */
    public float getSpeculativeSweep() {
        return speculativeSweep;
    }

    /**
     * Sets the speculative sweep.
     *
     * @param factor the factor, ≥ 0 (0 turns the sweep off; above 1 makes it wider)
     */
    public void setSpeculativeSweep(float factor) {
        speculativeSweep = Check.nonNegative("SolverSettings.setSpeculativeSweep", "factor", factor);
    }

    /**
     * How far two bodies may move relative to each other, counting the distance they can close in
     * the coming tick, before their contact is collided anew. Below it the contact keeps the points
     * it found last time, fixed on each body, and only their separations and normal follow the
     * bodies: a settled pile then costs almost no narrowphase. At most half the speculative distance
     * is used, so that a gap the last collision found beyond that distance cannot close unseen.
     * Default 0.1 px; 0 collides every contact every tick.
     *
     * @return the distance (px)
     */
    public float getManifoldReuseDistance() {
        return manifoldReuseDistance;
    }

    /**
     * Sets the manifold reuse distance.
     *
     * @param px the distance (px), ≥ 0 (0 turns reuse off)
     */
    public void setManifoldReuseDistance(float px) {
        manifoldReuseDistance = Check.nonNegative("SolverSettings.setManifoldReuseDistance", "px", px);
    }

    /**
     * How much the broadphase's boxes exceed the shapes, so slowly moving bodies do not touch the
     * tree every tick. Default 2 px (Box2D: 0.1 m).
     *
     * @return the margin (px)
     */
    public float getAabbMargin() {
        return aabbMargin;
    }

    /**
     * Sets the broadphase margin. It takes effect at the world's next tick: every body's box, static
     * and frozen ones too, is re-fattened to the new margin and its pairs are looked up again, a
     * one-off cost like moving every body once.
     *
     * @param px the margin (px), ≥ 0
     */
    public void setAabbMargin(float px) {
        aabbMargin = Check.nonNegative("SolverSettings.setAabbMargin", "px", px);
    }

    /**
     * Stiffness of contacts as a natural frequency. It is capped at a quarter of the substep rate
     * (beyond that the soft contact loses its stability margin), and contacts with static bodies use
     * twice the value. Default 240 Hz, so the cap decides: 50 Hz at 20 ticks per second and 10
     * iterations, 150 Hz at 60 and 10. Box2D v3 uses 30 Hz; we measured that stiffer contacts are
     * what keeps tall stacks from buckling (a soft contact is a spring, and a tower on springs
     * topples once its weight times its height exceeds their rotational stiffness).
     *
     * @return the contact frequency (Hz)
     */
    public float getContactHertz() {
        return contactHertz;
    }

    /**
     * Sets the contact stiffness.
     *
     * @param hertz the frequency (Hz), &gt; 0
     */
    public void setContactHertz(float hertz) {
        contactHertz = Check.positive("SolverSettings.setContactHertz", "hertz", hertz);
    }

    /**
     * Damping ratio of contacts; large values push overlap out without bounce. Default 10 (Box2D v3).
     *
     * @return the damping ratio
     */
    public float getContactDampingRatio() {
        return contactDampingRatio;
    }

    /**
     * Sets the contact damping ratio.
     *
     * @param ratio the ratio, ≥ 0
     */
    public void setContactDampingRatio(float ratio) {
        contactDampingRatio = Check.nonNegative("SolverSettings.setContactDampingRatio", "ratio", ratio);
    }

    /**
     * Largest speed at which overlapping bodies are pushed apart. Default 60 px/s (Box2D v3: 3 m/s).
     *
     * @return the speed (px/s)
     */
    public float getContactPushMaxVelocity() {
        return contactPushMaxVelocity;
    }

    /**
     * Sets the push-out speed cap.
     *
     * @param pxPerSecond the speed (px/s), &gt; 0
     */
    public void setContactPushMaxVelocity(float pxPerSecond) {
        contactPushMaxVelocity = Check.positive("SolverSettings.setContactPushMaxVelocity", "pxPerSecond", pxPerSecond);
    }

    /**
     * Largest speed at which a joint or rigid spring pulls its anchors together to correct an error.
     * Default 1000 px/s: with the default joint softness (about 64/s at 20 ticks/s and 10
     * iterations) errors up to about 15 px are corrected at the full soft rate, larger ones, such
     * as a joint created far from satisfied, at this speed instead of an impulse that flings the
     * bodies (the role of Box2D 2.4's maximum linear correction per step).
     *
     * @return the speed (px/s)
     */
    public float getJointPushMaxVelocity() {
        return jointPushMaxVelocity;
    }

    /**
     * Sets the joint correction speed cap.
     *
     * @param pxPerSecond the speed (px/s), &gt; 0
     */
    public void setJointPushMaxVelocity(float pxPerSecond) {
        jointPushMaxVelocity = Check.positive("SolverSettings.setJointPushMaxVelocity", "pxPerSecond", pxPerSecond);
    }

    /**
     * Approach speed below which contacts do not bounce, so resting bodies do not jitter.
     * Default 10 px/s (Box2D v3: 1 m/s; the original: 1/16 px per tick).
     *
     * @return the threshold (px/s)
     */
    public float getRestitutionThreshold() {
        return restitutionThreshold;
    }

    /**
     * Sets the restitution threshold.
     *
     * @param pxPerSecond the speed (px/s), ≥ 0
     */
    public void setRestitutionThreshold(float pxPerSecond) {
        restitutionThreshold = Check.nonNegative("SolverSettings.setRestitutionThreshold", "pxPerSecond", pxPerSecond);
    }

    /**
     * In dynamic-iteration mode, the solver counts as converged once no constraint changed a
     * relative velocity by more than this in a relax pass. Default 0.02 px/s: measured, towers of 40
     * boxes stand at 20 and 60 ticks per second with about 6 to 8 of 10 iterations; at 0.5 px/s a
     * tower of 10 falls.
     *
     * @return the tolerance (px/s)
     */
    public float getConvergenceTolerance() {
        return convergenceTolerance;
    }

    /**
     * Sets the convergence tolerance.
     *
     * @param pxPerSecond the tolerance (px/s), &gt; 0
     */
    public void setConvergenceTolerance(float pxPerSecond) {
        convergenceTolerance = Check.positive("SolverSettings.setConvergenceTolerance", "pxPerSecond", pxPerSecond);
    }

    /**
     * Stiffness of the position correction of rigid joints, as a natural frequency, capped at twice
     * the contact cap ({@link #getSubstepHertzRatio()}), half the substep rate by default: as stiff
     * as a contact with a static body, so a joint pulled against one does not give way. Default 60 Hz
     * (Box2D v3's setting; Box2D v3 caps it at an eighth of the substep rate).
     *
     * @return the joint frequency (Hz)
     */
    public float getJointHertz() {
        return jointHertz;
    }

    /**
     * Sets the joint stiffness.
     *
     * @param hertz the frequency (Hz), &gt; 0
     */
    public void setJointHertz(float hertz) {
        jointHertz = Check.positive("SolverSettings.setJointHertz", "hertz", hertz);
    }

    /**
     * Damping ratio of the position correction of rigid joints. Default 2 (Box2D v3).
     *
     * @return the damping ratio
     */
    public float getJointDampingRatio() {
        return jointDampingRatio;
    }

    /**
     * Sets the joint damping ratio.
     *
     * @param ratio the ratio, ≥ 0
     */
    public void setJointDampingRatio(float ratio) {
        jointDampingRatio = Check.nonNegative("SolverSettings.setJointDampingRatio", "ratio", ratio);
    }

    /**
     * A relax pass that changes a body's speed by more than this marks the body for further relax
     * passes in the same substep (up to {@link #getImpactRelaxPasses()}), over its contacts only.
     * Gravity changes a resting body by g·h per substep (0.5 px/s at the defaults), far below, so
     * resting scenes never pay for them; an impact does. Default 5 px/s: measured, a 1:100 heavy
     * box dropped on a light one rebounds at 14 px/s with it (pymunk: 15) instead of 160.
     *
     * @return the tolerance (px/s)
     */
    public float getImpactTolerance() {
        return impactTolerance;
    }

    /**
     * Sets the impact tolerance.
     *
     * @param pxPerSecond the speed change (px/s), &gt; 0
     */
    public void setImpactTolerance(float pxPerSecond) {
        impactTolerance = Check.positive("SolverSettings.setImpactTolerance", "pxPerSecond", pxPerSecond);
    }

    /**
     * Most relax passes per substep over the contacts of bodies an impact moved (see
     * {@link #getImpactTolerance()}). Default 100; 0 turns them off (Box2D v3's plain soft step).
     * Gauss–Seidel carries an impact through a column of n bodies in about n² passes: ten boxes
     * dropped together onto the ground at 20 ticks a second with elasticity 0 rebounded at 25–35% of
     * the impact speed with 10; with 30 at 2.6% as written but at 14.6% (the top two boxes leaving the
     * column) with gravity two parts per million weaker; with 100 at 0.7–2.6% either way
     * ({@code ColumnDropTest}). Passes run only while an impact still moves bodies, so the cap costs
     * what the impacts need: the tumbler benchmark, a pile that keeps tumbling, ran as fast with 100 as
     * with 30, and rain-5,000 while its bodies land 2-4% slower (2026-11-30).
     *
     * @return the passes
     */
    public int getImpactRelaxPasses() {
        return impactRelaxPasses;
    }

    /**
     * Sets the most impact relax passes per substep.
     *
     * @param passes the passes, ≥ 0
     */
    public void setImpactRelaxPasses(int passes) {
        if (passes < 0) {
            throw new IllegalArgumentException("SolverSettings.setImpactRelaxPasses: passes must be >= 0, was " + passes);
        }
        impactRelaxPasses = passes;
    }

    /**
     * How deep a contact may sink under its load before the solver takes more substeps. A soft
     * contact is a spring whose stiffness follows the lighter body's mass, so a heavy body resting
     * on a light one sinks by its weight over that stiffness: a 1:1000 box by 1.2 px at 20 ticks per
     * second and 10 iterations. Each tick the solver estimates every contact's sink from the impulse
     * it carried in the last tick and its bodies' masses; where one would sink deeper than this, it
     * takes more substeps (their stiffer cap makes the sink fall as their square), up to
     * {@link #getSinkSubstepFactor()} times the iteration count. Loads of equal bodies sink far less
     * (a tower of 50 boxes 0.013 px), so only such ticks pay. Default 0.5 px (ten linear slops);
     * infinity turns it off.
     *
     * @return the limit (px)
     */
    public float getSinkLimit() {
        return sinkLimit;
    }

    /**
     * Sets the sink limit.
     *
     * @param px the limit (px), &gt; 0, or infinity for none
     */
    public void setSinkLimit(float px) {
        if (!(px > 0f)) {
            throw new IllegalArgumentException("SolverSettings.setSinkLimit: px must be > 0 (infinity for no limit), was " + px);
        }
        sinkLimit = px;
    }

    /**
     * Most substeps the {@linkplain #getSinkLimit() sink limit} may take, as a multiple of the
     * iteration count, and never more than 1000 a tick. Default 2: a 1:1000 box then sinks 0.6 px at
     * the defaults; a 1:10,000 one would need 4.5 times the substeps (at twice it is still squeezed
     * out, as at 10).
     *
     * @return the factor, ≥ 1
     */
    public float getSinkSubstepFactor() {
        return sinkSubstepFactor;
    }

    /**
     * Sets the most substeps the sink limit may take.
     *
     * @param factor the factor, 1 (never more substeps) to 10
     */
    public void setSinkSubstepFactor(float factor) {
        if (!(factor >= 1f && factor <= 10f)) {
            throw new IllegalArgumentException("SolverSettings.setSinkSubstepFactor: factor must be in 1..10, was " + factor);
        }
        sinkSubstepFactor = factor;
    }

    /**
     * How deep the continuous pass leaves a fast body in what it would have passed through (px).
     * Default 0.25 px: four default linear slops plus 0.05 px, inside the speculative distance, so the
     * contact takes over in the next tick without a visible gap (Box2D v3 aims its time of impact at
     * a few linear slops for the same reason).
     *
     * @return the depth (px)
     */
    public float getTimeOfImpactTarget() {
        return timeOfImpactTarget;
    }

    /**
     * Sets the continuous pass's target depth.
     *
     * @param px the depth (px), &gt; 0
     */
    public void setTimeOfImpactTarget(float px) {
        timeOfImpactTarget = Check.positive("SolverSettings.setTimeOfImpactTarget", "px", px);
    }

    /**
     * The stiffest contact softness, as a fraction of the substep rate: the contact frequency is
     * capped at this ratio times 1/h, contacts with static bodies and rigid joints at twice that.
     * Default 0.25, as Box2D v3 caps its contact hertz at a quarter of the substep rate; stiffer
     * springs than that ring at the substep rate instead of acting stiffer.
     *
     * @return the ratio
     */
    public float getSubstepHertzRatio() {
        return substepHertzRatio;
    }

    /**
     * Sets the frequency cap as a fraction of the substep rate.
     *
     * @param ratio the ratio, in (0, 1]
     */
    public void setSubstepHertzRatio(float ratio) {
        Check.positive("SolverSettings.setSubstepHertzRatio", "ratio", ratio);
        substepHertzRatio = Check.unit("SolverSettings.setSubstepHertzRatio", "ratio", ratio);
    }

    /**
     * The largest condition number (k11² / det K) for which a two-point contact's normal impulses
     * are solved together as a block; more ill-conditioned pairs (nearly coincident points) are
     * solved point by point. Default 1000, Box2D 2.4's maximum condition number.
     *
     * @return the limit
     */
    public float getBlockConditionLimit() {
        return blockConditionLimit;
    }

    /**
     * Sets the block solver's condition limit.
     *
     * @param limit the limit, &ge; 1
     */
    public void setBlockConditionLimit(float limit) {
        Check.finite("SolverSettings.setBlockConditionLimit", "limit", limit);
        if (limit < 1f) {
            throw new IllegalArgumentException("SolverSettings.setBlockConditionLimit: limit must be >= 1, was " + limit);
        }
        blockConditionLimit = limit;
    }

    /**
     * The most contacts a world keeps, so that a pile-up bounds the tick's time and memory rather
     * than exhausting them: n bodies created in one spot make n(n − 1)/2 contacts, 50 million for
     * 10,000. A world at its capacity gives no contact to new pairs (those bodies pass through each
     * other until contacts end and make room) and says so ({@code World.isContactCapacityReached()});
     * the broadphase, too, stops collecting pairs at this many per tick. A contact costs about 400
     * bytes with its solver data and about 4 µs a tick in a crowd, so the default, 2²⁰ (1,048,576),
     * allows some 400 MB and a few seconds a tick: lower it on small devices.
     *
     * @return the capacity (contacts)
     */
    public int getMaxContacts() {
        return maxContacts;
    }

    /**
     * Sets the contact capacity; a world over it keeps its contacts and makes no new ones.
     *
     * @param contacts the capacity, &gt; 0
     */
    public void setMaxContacts(int contacts) {
        if (contacts <= 0) {
            throw new IllegalArgumentException("SolverSettings.setMaxContacts: contacts must be > 0, was " + contacts);
        }
        maxContacts = contacts;
    }

    /**
     * The speed below which a body rests, for sleeping. Default 1 px/s (Box2D v3: 0.05 m/s, for
     * bodies of about a metre; here, 5% of a 20 px body's size per second).
     *
     * @return the speed (px/s)
     */
    public float getSleepLinearTolerance() {
        return sleepLinearTolerance;
    }

    /**
     * Sets the speed below which a body rests, for sleeping.
     *
     * @param pxPerSecond the speed (px/s), &gt; 0
     */
    public void setSleepLinearTolerance(float pxPerSecond) {
        sleepLinearTolerance = Check.positive("SolverSettings.setSleepLinearTolerance", "pxPerSecond", pxPerSecond);
    }

    /**
     * The angular speed below which a body rests, for sleeping. Default 2°/s (Box2D's).
     *
     * @return the angular speed (rad/s)
     */
    public float getSleepAngularTolerance() {
        return sleepAngularTolerance;
    }

    /**
     * Sets the angular speed below which a body rests, for sleeping.
     *
     * @param radiansPerSecond the angular speed (rad/s), &gt; 0
     */
    public void setSleepAngularTolerance(float radiansPerSecond) {
        sleepAngularTolerance = Check.positive("SolverSettings.setSleepAngularTolerance", "radiansPerSecond",
            radiansPerSecond);
    }

    /**
     * How long a body and everything it touches must rest before they sleep. Default 0.5 s (Box2D's).
     *
     * @return the time (s)
     */
    public float getTimeToSleep() {
        return timeToSleep;
    }

    /**
     * Sets how long bodies must rest before they sleep.
     *
     * @param seconds the time (s), &gt; 0
     */
    public void setTimeToSleep(float seconds) {
        timeToSleep = Check.positive("SolverSettings.setTimeToSleep", "seconds", seconds);
    }

    /** The smallest length scale: tolerances a thousandth of the defaults (bodies of about 0.02 px). */
    public static final float MIN_LENGTH_SCALE = 1e-3f;
    /** The largest length scale: tolerances a thousand times the defaults (bodies of about 20,000 px). */
    public static final float MAX_LENGTH_SCALE = 1e3f;

    /**
     * The size of the world's typical body relative to the 20 px bodies the defaults are tuned for.
     * Default 1.
     *
     * @return the scale
     */
    public float getLengthScale() {
        return lengthScale;
    }

    /**
     * Sets the size of the world's typical body relative to 20 px (0.025 for 0.5 px bodies, 25 for
     * 500 px ones; Box2D v3's length units per metre, over 20): every length and speed tolerance
     * (linear slop, speculative distance, manifold reuse distance, broadphase margin, contact and joint push speeds,
     * restitution threshold, convergence and impact tolerances, time-of-impact depth, sleep speed)
     * is multiplied by the
     * ratio of the new scale to the old, so a scene scaled in size (and gravity) behaves as the
     * original. Frequencies, ratios and times do not scale. Set it before tuning single tolerances,
     * which it scales too. Shapes still need {@code Shape.MIN_SIZE} (0.25 px) across, so at small
     * scales the thinnest parts bound the scale from below.
     *
     * @param scale the scale, from {@link #MIN_LENGTH_SCALE} to {@link #MAX_LENGTH_SCALE}
     */
    public void setLengthScale(float scale) {
        if (!(scale >= MIN_LENGTH_SCALE && scale <= MAX_LENGTH_SCALE)) {
            throw new IllegalArgumentException("SolverSettings.setLengthScale: scale must be in " + MIN_LENGTH_SCALE + ".."
                + MAX_LENGTH_SCALE + ", was " + scale);
        }
        float r = scale / lengthScale;
        lengthScale = scale;
        linearSlop *= r;
        speculativeDistance *= r;
        manifoldReuseDistance *= r;
        aabbMargin *= r;
        contactPushMaxVelocity *= r;
        jointPushMaxVelocity *= r;
        restitutionThreshold *= r;
        convergenceTolerance *= r;
        impactTolerance *= r;
        timeOfImpactTarget *= r;
        sinkLimit *= r;
        sleepLinearTolerance *= r;
    }
}
