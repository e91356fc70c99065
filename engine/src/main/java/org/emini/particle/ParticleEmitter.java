package org.emini.particle;

import org.emini.dynamics.Body;
import org.emini.internal.Check;
import org.emini.math.EMath;

/**
 * A source of particles, fixed in the world or attached to a body, with its own pool of at most
 * {@link #getMaxParticles()} particles.
 *
 * <p>Particles are born along the segment between two emit points at {@link #getCreationRate()}
 * particles per second, live {@link #getLifetime()} seconds, start at {@link #getSpeed()} px/s in
 * the direction {@link #getAngle()} (0 = +x, π/2 = +y, down the screen), and each of these four
 * values gets a uniform random deviation: the value is drawn from [value − deviation/2,
 * value + deviation/2]. The draws come from a generator owned by the emitter and seeded with
 * {@link #setSeed(long)}, so a world with the same seeds gives bit-identical particles.
 *
 * <p>On a body the emit points are body-local offsets, rotated with the body, and so is the emit
 * angle, unless the axes are fixed ({@link #setAxesFixed(boolean)}): then both are world-aligned
 * offsets from the body's position. A particle leaves with its emit velocity plus the velocity of
 * the point it leaves from (the body's velocity plus ω × r; only the body's velocity when the axes
 * are fixed). An emit point inside an interacting body makes particles that are pushed out of it at
 * once: put emit points on or outside the body's surface.
 *
 * <p>Particles move under gravity × {@link #getGravityFactor()}, lose {@link #getDamping()} of their
 * velocity each tick, bounce off interacting bodies (static or dynamic, whatever their collision
 * layers) and the landscape (from either side: faces do not matter to particles, as in the
 * original) with the emitter's {@link #getElasticity()}, and never touch each other or push
 * anything. Births are spread over the tick: a particle born part-way through a tick has
 * already moved for the rest of it, so a fast emitter makes a continuous stream, not one puff per
 * tick.
 *
 * <p>Defaults are the original designer's "new emitter": rate 20/s, lifetime 2 s, speed 10 px/s,
 * angle 0, all deviations 0, elasticity 1, gravity factor 1, damping 0, axes not fixed, both emit
 * points at (0, 0), collisions on.
 *
 * <p>Supported ranges, checked by every setter (an {@link IllegalArgumentException} names the call
 * and the value): at most {@link #MAX_PARTICLES} particles; emit points within
 * ±{@link #MAX_COORDINATE} px; speeds within ±{@link #MAX_SPEED} px/s; rates up to
 * {@link #MAX_RATE} per second; lifetimes up to {@link #MAX_LIFETIME} s; angles within
 * ±{@link #MAX_ANGLE} rad; gravity factors within ±{@link #MAX_GRAVITY_FACTOR}; deviations from 0
 * to the same limits. The pool's arrays grow by doubling as particles need them, up to the maximum,
 * so a large maximum costs memory only when the particles live; once grown, ticks allocate nothing.
 * A tick emits at most as many particles as the pool holds, and of a tick longer than the longest
 * lifetime only its last lifetime emits (earlier births would be dead by its end).
 *
 * <p>Read the particles for drawing with {@link #getParticleCount()}, {@link #getX(int)},
 * {@link #getY(int)} and {@link #getAge(int)}, or {@link #copyPositions(float[])}; none of them
 * allocates. Particle indices change when particles die (the last one takes the dead one's place).
 * Change settings only between ticks.
 */
public final class ParticleEmitter {
    /** Creation rate of a new emitter (particles/s). */
    public static final float DEFAULT_CREATION_RATE = 20f;
    /** Lifetime of a new emitter's particles (s). */
    public static final float DEFAULT_LIFETIME = 2f;
    /** Emit speed of a new emitter (px/s). */
    public static final float DEFAULT_SPEED = 10f;
    /** Elasticity of a new emitter. */
    public static final float DEFAULT_ELASTICITY = 1f;
    /** Gravity factor of a new emitter. */
    public static final float DEFAULT_GRAVITY_FACTOR = 1f;
    /** Seed of a new emitter's generator. */
    public static final long DEFAULT_SEED = 0x5DEECE66DL;
    /** The largest pool (particles): 2²⁰, 32 MiB of particle state. */
    public static final int MAX_PARTICLES = 1 << 20;
    /** The largest emit point coordinate, either sign (px): floats are coarser than 1 px beyond 2²⁴. */
    public static final float MAX_COORDINATE = 1e7f;
    /** The largest emit speed and speed deviation (px/s). */
    public static final float MAX_SPEED = 1e6f;
    /** The largest creation rate and rate deviation (particles/s). */
    public static final float MAX_RATE = 1e6f;
    /** The longest lifetime and lifetime deviation (s). */
    public static final float MAX_LIFETIME = 1e6f;
    /** The largest emit angle, either sign, and angle deviation (rad). */
    public static final float MAX_ANGLE = 1e4f;
    /** The largest gravity factor, either sign. */
    public static final float MAX_GRAVITY_FACTOR = 1e4f;
    /** The pool's first size; it doubles up to the maximum as particles need it. */
    private static final int FIRST_CAPACITY = 16;

    private final Body body;
    private int maxParticles;
    private float rate = DEFAULT_CREATION_RATE;
    private float rateDeviation;
    private float lifetime = DEFAULT_LIFETIME;
    private float lifetimeDeviation;
    private float speed = DEFAULT_SPEED;
    private float speedDeviation;
    private float angle;
    private float angleDeviation;
    private float angleCos = 1f;
    private float angleSin;
    private float emitX1;
    private float emitY1;
    private float emitX2;
    private float emitY2;
    private boolean axesFixed;
    private boolean canCollide = true;
    private float elasticity = DEFAULT_ELASTICITY;
    private float gravityFactor = DEFAULT_GRAVITY_FACTOR;
    private float damping;
    private long seed = DEFAULT_SEED;
    private final ParticleRandom random = new ParticleRandom(DEFAULT_SEED);

    /** Fraction of a particle owed by continuous emission, carried from tick to tick. */
    private float owed;

    // The pool: live particles are 0 .. count-1, in arrays of the same length, at most maxParticles.
    // startX/Y hold where this tick's motion began.
    int count;
    float[] x;
    float[] y;
    float[] vx;
    float[] vy;
    float[] age;
    float[] life;
    float[] startX;
    float[] startY;

    /** Particles from here on were born in the current tick and moved only for their age. */
    int firstNew;
    /** The box around every particle's motion of the current tick. */
    float minX;
    float minY;
    float maxX;
    float maxY;

    ParticleSystem system;

    /**
     * Creates an emitter fixed in the world.
     *
     * @param maxParticles the pool size: the most particles alive at once, 1 to {@link #MAX_PARTICLES}
     */
    public ParticleEmitter(int maxParticles) {
        this(maxParticles, null);
    }

    /**
     * Creates an emitter attached to a body, or fixed in the world.
     *
     * @param maxParticles the pool size: the most particles alive at once, 1 to {@link #MAX_PARTICLES}
     * @param body the body that carries the emitter, or null for an emitter fixed in the world
     */
    public ParticleEmitter(int maxParticles, Body body) {
        this.body = body;
        this.maxParticles = checkMax("ParticleEmitter(maxParticles, body)", maxParticles);
        resize(Math.min(maxParticles, FIRST_CAPACITY));
    }

    /** Gives the pool's arrays the new length, keeping the live particles that fit. */
    private void resize(int length) {
        x = copy(x, length);
        y = copy(y, length);
        vx = copy(vx, length);
        vy = copy(vy, length);
        age = copy(age, length);
        life = copy(life, length);
        startX = copy(startX, length);
        startY = copy(startY, length);
    }

    private float[] copy(float[] a, int length) {
        float[] grown = new float[length];
        if (a != null) {
            System.arraycopy(a, 0, grown, 0, Math.min(count, length));
        }
        return grown;
    }

    /** Room for n more particles, growing the arrays by doubling (n must fit under the maximum). */
    private void ensureRoom(int n) {
        if (count + n > x.length) {
            resize((int) Math.min(maxParticles, Math.max(count + (long) n, 2L * x.length)));
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Settings

    /**
     * The body that carries the emitter.
     *
     * @return the body, or null for an emitter fixed in the world
     */
    public Body getBody() {
        return body;
    }

    /**
     * The pool size: the most particles alive at once. Emission pauses while the pool is full.
     *
     * @return the maximum particle count
     */
    public int getMaxParticles() {
        return maxParticles;
    }

    /**
     * Changes the pool size. When it shrinks below the live count, the particles with the highest
     * indices are dropped (and the arrays shrink, which allocates).
     *
     * @param maxParticles the new maximum, 1 to {@link #MAX_PARTICLES}
     */
    public void setMaxParticles(int maxParticles) {
        this.maxParticles = checkMax("ParticleEmitter.setMaxParticles", maxParticles);
        if (x.length > maxParticles) {
            count = Math.min(count, maxParticles);
            firstNew = Math.min(firstNew, count);
            resize(maxParticles);
        }
    }

    /**
     * The mean creation rate.
     *
     * @return particles per second
     */
    public float getCreationRate() {
        return rate;
    }

    /**
     * The full width of the creation rate's random deviation, drawn once per tick.
     *
     * @return particles per second
     */
    public float getCreationRateDeviation() {
        return rateDeviation;
    }

    /**
     * Sets the creation rate. Each tick draws a rate from [rate − deviation/2, rate + deviation/2]
     * (below zero counts as zero); the fraction of a particle left over carries to the next tick,
     * so the long-run mean is exactly the rate.
     *
     * @param rate particles per second, 0 to {@link #MAX_RATE}
     * @param deviation the full width of the deviation, 0 to {@link #MAX_RATE}
     */
    public void setCreationRate(float rate, float deviation) {
        this.rate = Check.within("ParticleEmitter.setCreationRate", "rate", rate, 0f, MAX_RATE);
        rateDeviation = Check.within("ParticleEmitter.setCreationRate", "deviation", deviation, 0f, MAX_RATE);
    }

    /**
     * The mean lifetime of a particle.
     *
     * @return seconds
     */
    public float getLifetime() {
        return lifetime;
    }

    /**
     * The full width of the lifetime's random deviation.
     *
     * @return seconds
     */
    public float getLifetimeDeviation() {
        return lifetimeDeviation;
    }

    /**
     * Sets the lifetime: each particle lives a time drawn from [seconds − deviation/2,
     * seconds + deviation/2] and dies in the tick in which its age reaches it.
     *
     * @param seconds the mean lifetime (s), &gt; 0 and at most {@link #MAX_LIFETIME}
     * @param deviation the full width of the deviation (s), 0 to {@link #MAX_LIFETIME}
     */
    public void setLifetime(float seconds, float deviation) {
        lifetime = Check.within("ParticleEmitter.setLifetime", "seconds", Check.positive("ParticleEmitter.setLifetime",
            "seconds", seconds), 0f, MAX_LIFETIME);
        lifetimeDeviation = Check.within("ParticleEmitter.setLifetime", "deviation", deviation, 0f, MAX_LIFETIME);
    }

    /**
     * The mean emit speed, relative to the emit point.
     *
     * @return px/s
     */
    public float getSpeed() {
        return speed;
    }

    /**
     * The full width of the emit speed's random deviation.
     *
     * @return px/s
     */
    public float getSpeedDeviation() {
        return speedDeviation;
    }

    /**
     * Sets the emit speed: each particle leaves at a speed drawn from [speed − deviation/2,
     * speed + deviation/2] relative to its emit point.
     *
     * @param speed the mean speed (px/s), within ±{@link #MAX_SPEED}
     * @param deviation the full width of the deviation (px/s), 0 to {@link #MAX_SPEED}
     */
    public void setSpeed(float speed, float deviation) {
        this.speed = Check.within("ParticleEmitter.setSpeed", "speed", speed, -MAX_SPEED, MAX_SPEED);
        speedDeviation = Check.within("ParticleEmitter.setSpeed", "deviation", deviation, 0f, MAX_SPEED);
    }

    /**
     * The mean emit direction.
     *
     * @return radians; 0 = +x, π/2 = +y (down the screen)
     */
    public float getAngle() {
        return angle;
    }

    /**
     * The full width of the emit direction's random deviation (2π emits in every direction).
     *
     * @return radians
     */
    public float getAngleDeviation() {
        return angleDeviation;
    }

    /**
     * Sets the emit direction: each particle leaves at an angle drawn from [radians − deviation/2,
     * radians + deviation/2], plus the body's angle unless the axes are fixed.
     *
     * @param radians the mean direction; 0 = +x, π/2 = +y (down the screen); within ±{@link #MAX_ANGLE}
     * @param deviation the full width of the deviation (rad), 0 to {@link #MAX_ANGLE}
     */
    public void setAngle(float radians, float deviation) {
        angle = Check.within("ParticleEmitter.setAngle", "radians", radians, -MAX_ANGLE, MAX_ANGLE);
        angleDeviation = Check.within("ParticleEmitter.setAngle", "deviation", deviation, 0f, MAX_ANGLE);
        angleCos = EMath.cos(radians);
        angleSin = EMath.sin(radians);
    }

    /**
     * Emits from one point (both emit points set to it).
     *
     * @param x world x, or body-local x on a body (px), within ±{@link #MAX_COORDINATE}
     * @param y world y, or body-local y on a body (px), within ±{@link #MAX_COORDINATE}
     */
    public void setEmitPoint(float x, float y) {
        setEmitSegment(x, y, x, y);
    }

    /**
     * Emits from uniformly random points of the segment between two points.
     *
     * @param x1 the first point's x: world, or body-local on a body (px), within ±{@link #MAX_COORDINATE}
     * @param y1 the first point's y (px), within ±{@link #MAX_COORDINATE}
     * @param x2 the second point's x (px), within ±{@link #MAX_COORDINATE}
     * @param y2 the second point's y (px), within ±{@link #MAX_COORDINATE}
     */
    public void setEmitSegment(float x1, float y1, float x2, float y2) {
        String where = "ParticleEmitter.setEmitSegment";
        emitX1 = Check.within(where, "x1", x1, -MAX_COORDINATE, MAX_COORDINATE);
        emitY1 = Check.within(where, "y1", y1, -MAX_COORDINATE, MAX_COORDINATE);
        emitX2 = Check.within(where, "x2", x2, -MAX_COORDINATE, MAX_COORDINATE);
        emitY2 = Check.within(where, "y2", y2, -MAX_COORDINATE, MAX_COORDINATE);
    }

    /**
     * The first emit point's x.
     *
     * @return world x, or body-local x on a body (px)
     */
    public float getEmitX1() {
        return emitX1;
    }

    /**
     * The first emit point's y.
     *
     * @return world y, or body-local y on a body (px)
     */
    public float getEmitY1() {
        return emitY1;
    }

    /**
     * The second emit point's x.
     *
     * @return world x, or body-local x on a body (px)
     */
    public float getEmitX2() {
        return emitX2;
    }

    /**
     * The second emit point's y.
     *
     * @return world y, or body-local y on a body (px)
     */
    public float getEmitY2() {
        return emitY2;
    }

    /**
     * Whether the emit points and angle ignore the body's rotation.
     *
     * @return true when the axes are fixed
     */
    public boolean isAxesFixed() {
        return axesFixed;
    }

    /**
     * Makes the emit points and angle ignore the body's rotation (world-aligned offsets from the
     * body's position) or turn with it (the default). Has no effect without a body.
     *
     * @param fixed true to fix the axes
     */
    public void setAxesFixed(boolean fixed) {
        axesFixed = fixed;
    }

    /**
     * Whether the particles bounce off bodies and the landscape.
     *
     * @return true when they collide (the default)
     */
    public boolean canCollide() {
        return canCollide;
    }

    /**
     * Lets the particles bounce off bodies and the landscape, or fly through everything (cheaper).
     *
     * @param collide true to collide
     */
    public void setCanCollide(boolean collide) {
        canCollide = collide;
    }

    /**
     * The fraction of the normal speed a particle keeps when it bounces (the surface's own material
     * is not consulted, as in the original).
     *
     * @return the elasticity, in [0, 1]
     */
    public float getElasticity() {
        return elasticity;
    }

    /**
     * Sets the fraction of the normal speed (relative to the surface) a particle keeps when it
     * bounces; the tangential speed is kept whole.
     *
     * @param elasticity the elasticity, in [0, 1]
     */
    public void setElasticity(float elasticity) {
        this.elasticity = Check.unit("ParticleEmitter.setElasticity", "elasticity", elasticity);
    }

    /**
     * The multiplier on the world's gravity for these particles.
     *
     * @return the factor
     */
    public float getGravityFactor() {
        return gravityFactor;
    }

    /**
     * Sets the multiplier on the world's gravity: 0 for weightless sparks, negative for smoke that
     * rises.
     *
     * @param factor the factor, within ±{@link #MAX_GRAVITY_FACTOR}
     */
    public void setGravityFactor(float factor) {
        gravityFactor = Check.within("ParticleEmitter.setGravityFactor", "factor", factor, -MAX_GRAVITY_FACTOR,
            MAX_GRAVITY_FACTOR);
    }

    /**
     * The fraction of a particle's velocity removed each tick.
     *
     * @return the damping, in [0, 1]
     */
    public float getDamping() {
        return damping;
    }

    /**
     * Sets the fraction of a particle's velocity removed at the end of each tick.
     *
     * @param damping the damping, in [0, 1]
     */
    public void setDamping(float damping) {
        this.damping = Check.unit("ParticleEmitter.setDamping", "damping", damping);
    }

    /**
     * The seed last given to the generator.
     *
     * @return the seed
     */
    public long getSeed() {
        return seed;
    }

    /**
     * Restarts the emitter's random generator from a seed; the same seed and the same ticks give
     * bit-identical particles.
     *
     * @param seed any value
     */
    public void setSeed(long seed) {
        this.seed = seed;
        random.setSeed(seed);
    }

    // ---------------------------------------------------------------------------------------------
    // Particles

    /**
     * Emits particles now, at the emitter's current position, with the emitter's random speed,
     * angle and lifetime and age 0: a burst (an explosion, a splash), on top of the continuous
     * rate. Stops when the pool is full.
     *
     * @param particles how many, &ge; 0
     * @return how many were emitted
     */
    public int emit(int particles) {
        if (particles < 0) {
            throw new IllegalArgumentException("ParticleEmitter.emit: particles must be >= 0, was " + particles);
        }
        int n = Math.min(particles, maxParticles - count);
        ensureRoom(n);
        for (int k = 0; k < n; k++) {
            float l = drawLifetime();
            spawn(0f, l, 0f, 0f);
        }
        return n;
    }

    /** Removes every particle. */
    public void clear() {
        count = 0;
        firstNew = 0;
    }

    /**
     * The number of live particles.
     *
     * @return the count
     */
    public int getParticleCount() {
        return count;
    }

    /**
     * A particle's x.
     *
     * @param i 0 to {@link #getParticleCount()} − 1
     * @return x (px)
     */
    public float getX(int i) {
        return x[check("ParticleEmitter.getX", i)];
    }

    /**
     * A particle's y.
     *
     * @param i 0 to {@link #getParticleCount()} − 1
     * @return y (px)
     */
    public float getY(int i) {
        return y[check("ParticleEmitter.getY", i)];
    }

    /**
     * A particle's x velocity.
     *
     * @param i 0 to {@link #getParticleCount()} − 1
     * @return vx (px/s)
     */
    public float getVelocityX(int i) {
        return vx[check("ParticleEmitter.getVelocityX", i)];
    }

    /**
     * A particle's y velocity.
     *
     * @param i 0 to {@link #getParticleCount()} − 1
     * @return vy (px/s)
     */
    public float getVelocityY(int i) {
        return vy[check("ParticleEmitter.getVelocityY", i)];
    }

    /**
     * The time since a particle was born.
     *
     * @param i 0 to {@link #getParticleCount()} − 1
     * @return the age (s)
     */
    public float getAge(int i) {
        return age[check("ParticleEmitter.getAge", i)];
    }

    /**
     * The lifetime drawn for a particle at its birth: it dies in the tick its age reaches this.
     *
     * @param i 0 to {@link #getParticleCount()} − 1
     * @return the lifetime (s)
     */
    public float getParticleLifetime(int i) {
        return life[check("ParticleEmitter.getParticleLifetime", i)];
    }

    /**
     * Copies the positions of the live particles as x0, y0, x1, y1, ...
     *
     * @param out an array of at least 2 × {@link #getParticleCount()} floats
     * @return the number of particles copied
     */
    public int copyPositions(float[] out) {
        if (out == null || out.length < 2 * count) {
            throw new IllegalArgumentException("ParticleEmitter.copyPositions: out must hold " + (2 * count)
                + " floats, was " + (out == null ? "null" : out.length + " long"));
        }
        for (int i = 0; i < count; i++) {
            out[2 * i] = x[i];
            out[2 * i + 1] = y[i];
        }
        return count;
    }

    @Override
    public String toString() {
        return "ParticleEmitter[" + count + " of " + maxParticles + " particles" + (body == null ? ", fixed" : ", on " + body) + "]";
    }

    // ---------------------------------------------------------------------------------------------
    // The tick (called by ParticleSystem)

    /**
     * Ages the particles, removes the dead, moves the rest one tick ballistically (exact for
     * constant gravity), then emits this tick's new particles; records where each motion started
     * and the box around all of them for the collision pass.
     */
    void advance(float dt, float gravityX, float gravityY) {
        float gx = gravityX * gravityFactor;
        float gy = gravityY * gravityFactor;
        if (!EMath.isFinite(gx) || !EMath.isFinite(gy)) {
            throw new IllegalStateException("ParticleEmitter: the world's gravity (" + gravityX + ", " + gravityY
                + ") times the gravity factor " + gravityFactor + " is beyond the float range");
        }
        float halfDt2 = 0.5f * dt * dt;
        minX = Float.POSITIVE_INFINITY;
        minY = Float.POSITIVE_INFINITY;
        maxX = Float.NEGATIVE_INFINITY;
        maxY = Float.NEGATIVE_INFINITY;
        float[] px = x;
        float[] py = y;
        float[] pvx = vx;
        float[] pvy = vy;
        float[] pa = age;
        float[] pl = life;
        float[] sx = startX;
        float[] sy = startY;
        int n = count;
        int i = 0;
        // Ages are sums of the timestep, which fall short in float (60 × 0.05 = 2.9999983): a
        // thousandth of a tick counts as reached, so no particle outlives its lifetime by a tick.
        float reached = 1e-3f * dt;
        while (i < n) {
            float a = pa[i] + dt;
            if (a >= pl[i] - reached) {
                n--;
                px[i] = px[n];
                py[i] = py[n];
                pvx[i] = pvx[n];
                pvy[i] = pvy[n];
                pa[i] = pa[n];
                pl[i] = pl[n];
                continue;
            }
            pa[i] = a;
            float x0 = px[i];
            float y0 = py[i];
            float ux = pvx[i];
            float uy = pvy[i];
            float x1 = x0 + ux * dt + gx * halfDt2;
            float y1 = y0 + uy * dt + gy * halfDt2;
            sx[i] = x0;
            sy[i] = y0;
            px[i] = x1;
            py[i] = y1;
            pvx[i] = ux + gx * dt;
            pvy[i] = uy + gy * dt;
            minX = Math.min(minX, Math.min(x0, x1));
            minY = Math.min(minY, Math.min(y0, y1));
            maxX = Math.max(maxX, Math.max(x0, x1));
            maxY = Math.max(maxY, Math.max(y0, y1));
            i++;
        }
        count = n;
        firstNew = n;
        emitContinuously(dt, gx, gy);
    }

    /** Removes the given fraction of every particle's velocity (the end-of-tick damping). */
    void damp() {
        if (damping == 0f) {
            return;
        }
        float keep = 1f - damping;
        for (int i = 0; i < count; i++) {
            vx[i] *= keep;
            vy[i] *= keep;
        }
    }

    /**
     * Emits the particles the rate owes this tick. Emission is continuous: birth k happens when
     * owed + rate·t reaches k, so each new particle has already lived and moved for the rest of the
     * tick. Of a tick longer than the longest lifetime only the last lifetime emits (the earlier
     * births are dead by its end), and at most a pool's worth of births is looked at, so a huge
     * timestep or rate costs no more than filling the pool.
     */
    private void emitContinuously(float dt, float gx, float gy) {
        float r = rate;
        if (rateDeviation != 0f) {
            r += rateDeviation * random.nextCentered();
        }
        if (!(r > 0f)) {
            return;
        }
        float span = Math.min(dt, lifetime + 0.5f * lifetimeDeviation);
        float before = owed;
        float total = before + r * span;
        int births = (int) total;
        // Beyond 2^24 a float has no fraction left to carry (and the int cast saturates).
        owed = total < 0x1p24f ? total - births : 0f;
        float step = 1f / r;
        for (int k = 1; k <= births && k <= maxParticles && count < maxParticles; k++) {
            float a = Math.max(0f, span - (k - before) * step);
            float l = drawLifetime();
            if (l <= a) {
                // Born and dead within this tick: it counts, but is never seen.
                continue;
            }
            spawn(a, l, gx, gy);
            includeInBounds(count - 1);
        }
    }

    private float drawLifetime() {
        return lifetimeDeviation == 0f ? lifetime : lifetime + lifetimeDeviation * random.nextCentered();
    }

    /**
     * Appends one particle that left the emitter a seconds ago (at the emitter's current place: the
     * emit point's own motion since then is the part of its velocity it shares with the body).
     */
    private void spawn(float a, float l, float gx, float gy) {
        ensureRoom(1);
        float lx = emitX1;
        float ly = emitY1;
        if (emitX1 != emitX2 || emitY1 != emitY2) {
            float u = random.nextFloat();
            lx += u * (emitX2 - emitX1);
            ly += u * (emitY2 - emitY1);
        }
        float dirX = angleCos;
        float dirY = angleSin;
        if (angleDeviation != 0f) {
            float theta = angle + angleDeviation * random.nextCentered();
            dirX = EMath.cos(theta);
            dirY = EMath.sin(theta);
        }
        float s = speedDeviation == 0f ? speed : speed + speedDeviation * random.nextCentered();
        float ex = lx;
        float ey = ly;
        float pointVx = 0f;
        float pointVy = 0f;
        if (body != null) {
            float bx = body.getX();
            float by = body.getY();
            float rx = lx;
            float ry = ly;
            pointVx = body.getVelocityX();
            pointVy = body.getVelocityY();
            if (!axesFixed) {
                float c = body.getCos();
                float sn = body.getSin();
                rx = c * lx - sn * ly;
                ry = sn * lx + c * ly;
                float t = c * dirX - sn * dirY;
                dirY = sn * dirX + c * dirY;
                dirX = t;
                float w = body.getAngularVelocity();
                pointVx -= w * ry;
                pointVy += w * rx;
            }
            ex = bx + rx;
            ey = by + ry;
        }
        float relX = s * dirX;
        float relY = s * dirY;
        int i = count++;
        startX[i] = ex;
        startY[i] = ey;
        x[i] = ex + relX * a + 0.5f * gx * a * a;
        y[i] = ey + relY * a + 0.5f * gy * a * a;
        vx[i] = relX + pointVx + gx * a;
        vy[i] = relY + pointVy + gy * a;
        age[i] = a;
        life[i] = l;
    }

    private void includeInBounds(int i) {
        minX = Math.min(minX, Math.min(startX[i], x[i]));
        minY = Math.min(minY, Math.min(startY[i], y[i]));
        maxX = Math.max(maxX, Math.max(startX[i], x[i]));
        maxY = Math.max(maxY, Math.max(startY[i], y[i]));
    }

    // ---------------------------------------------------------------------------------------------
    // Argument checks, naming the call and the value

    private int check(String where, int i) {
        if (i < 0 || i >= count) {
            throw new IndexOutOfBoundsException(where + ": index " + i + " of " + count + " particles");
        }
        return i;
    }

    private static int checkMax(String where, int max) {
        if (max <= 0 || max > MAX_PARTICLES) {
            throw new IllegalArgumentException(where + ": maxParticles must be in 1.." + MAX_PARTICLES + ", was " + max);
        }
        return max;
    }
}
