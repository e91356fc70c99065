package org.emini.io;

/**
 * A particle emitter record. Particles start at a uniformly random point of the segment from
 * position 1 to position 2: world coordinates without an emitter body, offsets from the body's
 * position with one (rotated with the body unless the axes are fixed). Whether particles collide
 * is not stored (the original's default: they do).
 */
public final class PhyParticleEmitter extends PhyElement {
    private int body = PhyWorld.NONE;
    private int axesFixed;
    private PhyVector position1 = PhyVector.ZERO;
    private PhyVector position2 = PhyVector.ZERO;
    private int emitAngle;
    private int emitAngleSpread;
    private int speed;
    private int speedSpread;
    private int rate;
    private int rateSpread;
    private int lifetime;
    private int lifetimeSpread;
    private int elasticity;
    private int gravityFactor;
    private int damping;
    private int maxParticles;

    /** Creates an emitter with all values 0, fixed in world space. */
    public PhyParticleEmitter() {
    }

    /**
     * The emitter body: a body index in file order, or {@link PhyWorld#NONE} for an emitter fixed
     * in world space.
     *
     * @return 0 to 255
     */
    public int getBody() {
        return body;
    }

    /**
     * Sets the emitter body.
     *
     * @param index a body index, or {@link PhyWorld#NONE}
     */
    public void setBody(int index) {
        body = PhyWorld.checkU8("PhyParticleEmitter.setBody", "index", index);
    }

    /**
     * The axes-fixed byte; a value other than 0 makes emission ignore the body's rotation.
     *
     * @return 0 to 255
     */
    public int getAxesFixedByte() {
        return axesFixed;
    }

    /**
     * Sets the axes-fixed byte.
     *
     * @param value 0 to 255
     */
    public void setAxesFixedByte(int value) {
        axesFixed = PhyWorld.checkU8("PhyParticleEmitter.setAxesFixedByte", "value", value);
    }

    /**
     * Whether emission ignores the emitter body's rotation.
     *
     * @return true when the axes-fixed byte is not 0
     */
    public boolean isAxesFixed() {
        return axesFixed != 0;
    }

    /**
     * The first end of the emission segment.
     *
     * @return the point (px)
     */
    public PhyVector getPosition1() {
        return position1;
    }

    /**
     * Sets the first end of the emission segment.
     *
     * @param p the point (px)
     */
    public void setPosition1(PhyVector p) {
        position1 = PhyWorld.checkNotNull("PhyParticleEmitter.setPosition1", "p", p);
    }

    /**
     * The second end of the emission segment.
     *
     * @return the point (px)
     */
    public PhyVector getPosition2() {
        return position2;
    }

    /**
     * Sets the second end of the emission segment.
     *
     * @param p the point (px)
     */
    public void setPosition2(PhyVector p) {
        position2 = PhyWorld.checkNotNull("PhyParticleEmitter.setPosition2", "p", p);
    }

    /**
     * The emission direction (0 = +x, π/2 = +y, down the screen), as stored (2FX).
     *
     * @return the raw value
     */
    public int getEmitAngleRaw() {
        return emitAngle;
    }

    /**
     * Sets the emission direction (0 = +x, π/2 = +y, down the screen) as stored.
     *
     * @param raw the raw 2FX value
     */
    public void setEmitAngleRaw(int raw) {
        emitAngle = raw;
    }

    /**
     * The emission direction (0 = +x, π/2 = +y, down the screen).
     *
     * @return raw / 2²⁴ (rad)
     */
    public float getEmitAngle() {
        return PhyFixed.fx2(emitAngle);
    }

    /**
     * The full width of the uniform random spread of the direction, as stored (2FX).
     *
     * @return the raw value
     */
    public int getEmitAngleSpreadRaw() {
        return emitAngleSpread;
    }

    /**
     * Sets the full width of the uniform random spread of the direction as stored.
     *
     * @param raw the raw 2FX value
     */
    public void setEmitAngleSpreadRaw(int raw) {
        emitAngleSpread = raw;
    }

    /**
     * The full width of the uniform random spread of the direction.
     *
     * @return raw / 2²⁴ (rad)
     */
    public float getEmitAngleSpread() {
        return PhyFixed.fx2(emitAngleSpread);
    }

    /**
     * The emission speed, as stored (FX).
     *
     * @return the raw value
     */
    public int getSpeedRaw() {
        return speed;
    }

    /**
     * Sets the emission speed as stored.
     *
     * @param raw the raw FX value
     */
    public void setSpeedRaw(int raw) {
        speed = raw;
    }

    /**
     * The emission speed.
     *
     * @return raw / 4096 (px/s)
     */
    public float getSpeed() {
        return PhyFixed.fx(speed);
    }

    /**
     * The full width of the random spread of the speed, as stored (FX).
     *
     * @return the raw value
     */
    public int getSpeedSpreadRaw() {
        return speedSpread;
    }

    /**
     * Sets the full width of the random spread of the speed as stored.
     *
     * @param raw the raw FX value
     */
    public void setSpeedSpreadRaw(int raw) {
        speedSpread = raw;
    }

    /**
     * The full width of the random spread of the speed.
     *
     * @return raw / 4096 (px/s)
     */
    public float getSpeedSpread() {
        return PhyFixed.fx(speedSpread);
    }

    /**
     * The creation rate, as stored (FX).
     *
     * @return the raw value
     */
    public int getRateRaw() {
        return rate;
    }

    /**
     * Sets the creation rate as stored.
     *
     * @param raw the raw FX value
     */
    public void setRateRaw(int raw) {
        rate = raw;
    }

    /**
     * The creation rate.
     *
     * @return raw / 4096 (particles/s)
     */
    public float getRate() {
        return PhyFixed.fx(rate);
    }

    /**
     * The random spread of the creation rate, as stored (FX).
     *
     * @return the raw value
     */
    public int getRateSpreadRaw() {
        return rateSpread;
    }

    /**
     * Sets the random spread of the creation rate as stored.
     *
     * @param raw the raw FX value
     */
    public void setRateSpreadRaw(int raw) {
        rateSpread = raw;
    }

    /**
     * The random spread of the creation rate.
     *
     * @return raw / 4096 (particles/s)
     */
    public float getRateSpread() {
        return PhyFixed.fx(rateSpread);
    }

    /**
     * A particle's lifetime, as stored (FX).
     *
     * @return the raw value
     */
    public int getLifetimeRaw() {
        return lifetime;
    }

    /**
     * Sets a particle's lifetime as stored.
     *
     * @param raw the raw FX value
     */
    public void setLifetimeRaw(int raw) {
        lifetime = raw;
    }

    /**
     * A particle's lifetime.
     *
     * @return raw / 4096 (s)
     */
    public float getLifetime() {
        return PhyFixed.fx(lifetime);
    }

    /**
     * The full width of the random spread of the lifetime, as stored (FX).
     *
     * @return the raw value
     */
    public int getLifetimeSpreadRaw() {
        return lifetimeSpread;
    }

    /**
     * Sets the full width of the random spread of the lifetime as stored.
     *
     * @param raw the raw FX value
     */
    public void setLifetimeSpreadRaw(int raw) {
        lifetimeSpread = raw;
    }

    /**
     * The full width of the random spread of the lifetime.
     *
     * @return raw / 4096 (s)
     */
    public float getLifetimeSpread() {
        return PhyFixed.fx(lifetimeSpread);
    }

    /**
     * The capacity: the most particles alive at once (a plain integer, not fixed point).
     *
     * @return the count as stored
     */
    public int getMaxParticles() {
        return maxParticles;
    }

    /**
     * Sets the capacity.
     *
     * @param count the count as stored
     */
    public void setMaxParticles(int count) {
        maxParticles = count;
    }

    /**
     * The bounce factor on collision, as stored (FX).
     *
     * @return the raw value
     */
    public int getElasticityRaw() {
        return elasticity;
    }

    /**
     * Sets the bounce factor on collision as stored.
     *
     * @param raw the raw FX value
     */
    public void setElasticityRaw(int raw) {
        elasticity = raw;
    }

    /**
     * The bounce factor on collision.
     *
     * @return raw / 4096 (ratio)
     */
    public float getElasticity() {
        return PhyFixed.fx(elasticity);
    }

    /**
     * The multiplier on world gravity, as stored (FX).
     *
     * @return the raw value
     */
    public int getGravityFactorRaw() {
        return gravityFactor;
    }

    /**
     * Sets the multiplier on world gravity as stored.
     *
     * @param raw the raw FX value
     */
    public void setGravityFactorRaw(int raw) {
        gravityFactor = raw;
    }

    /**
     * The multiplier on world gravity.
     *
     * @return raw / 4096 (ratio)
     */
    public float getGravityFactor() {
        return PhyFixed.fx(gravityFactor);
    }

    /**
     * The fraction of a particle's velocity removed per tick, as stored (FX).
     *
     * @return the raw value
     */
    public int getDampingRaw() {
        return damping;
    }

    /**
     * Sets the fraction of a particle's velocity removed per tick as stored.
     *
     * @param raw the raw FX value
     */
    public void setDampingRaw(int raw) {
        damping = raw;
    }

    /**
     * The fraction of a particle's velocity removed per tick.
     *
     * @return raw / 4096 (ratio)
     */
    public float getDamping() {
        return PhyFixed.fx(damping);
    }

    static PhyParticleEmitter read(PhyInput in, int bodiesSoFar) throws PhyFormatException {
        PhyParticleEmitter p = new PhyParticleEmitter();
        p.body = in.optionalIndex("body index", bodiesSoFar);
        p.axesFixed = in.u8("axes-fixed flag");
        p.position1 = in.vector("position 1");
        p.position2 = in.vector("position 2");
        p.emitAngle = in.i32("emit angle");
        p.emitAngleSpread = in.i32("emit angle spread");
        p.speed = in.i32("speed");
        p.speedSpread = in.i32("speed spread");
        p.rate = in.i32("rate");
        p.rateSpread = in.i32("rate spread");
        p.lifetime = in.i32("lifetime");
        p.lifetimeSpread = in.i32("lifetime spread");
        p.maxParticles = in.i32("max particles");
        p.elasticity = in.i32("elasticity");
        p.gravityFactor = in.i32("gravity factor");
        p.damping = in.i32("damping");
        p.readUserData(in, PhyVersion.othersHaveUserData(in.version()));
        return p;
    }

    void write(PhyOutput out) {
        out.optionalIndex("body index", body, out.bodies);
        out.u8(axesFixed);
        out.vector(position1);
        out.vector(position2);
        out.i32(emitAngle);
        out.i32(emitAngleSpread);
        out.i32(speed);
        out.i32(speedSpread);
        out.i32(rate);
        out.i32(rateSpread);
        out.i32(lifetime);
        out.i32(lifetimeSpread);
        out.i32(maxParticles);
        out.i32(elasticity);
        out.i32(gravityFactor);
        out.i32(damping);
        out.userData(PhyVersion.othersHaveUserData(out.version()), this);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PhyParticleEmitter)) {
            return false;
        }
        PhyParticleEmitter p = (PhyParticleEmitter) o;
        return body == p.body && axesFixed == p.axesFixed && position1.equals(p.position1)
                && position2.equals(p.position2) && maxParticles == p.maxParticles
                && emitAngle == p.emitAngle && emitAngleSpread == p.emitAngleSpread && speed == p.speed && speedSpread == p.speedSpread && rate == p.rate && rateSpread == p.rateSpread && lifetime == p.lifetime && lifetimeSpread == p.lifetimeSpread && elasticity == p.elasticity && gravityFactor == p.gravityFactor && damping == p.damping && userDataEquals(p);
    }

    @Override
    public int hashCode() {
        return ((body * 31 + position1.hashCode()) * 31 + position2.hashCode()) * 31 + rate + speed + maxParticles
                + userDataHash();
    }

    @Override
    public String toString() {
        return "PhyParticleEmitter[body " + body + ", rate " + getRate() + "/s, max " + maxParticles + "]";
    }
}
