package org.emini.dynamics;

import java.util.Arrays;

/**
 * What the last tick did, read-only until the next one: the bodies it simulated, each with its pose
 * at the tick's start (its end pose is the body's own), and the contacts that began and stopped
 * touching. Particles, events and the application read it instead of recomputing it.
 *
 * <p>A contact touches when the narrowphase, at the tick's start, finds a point of it at or inside
 * zero separation; it stops touching when none is within {@link SolverSettings#getSpeculativeDistance()}
 * any more, or when it ends (its bodies' boxes part, or the application removes one of its bodies
 * or changes its shape, kind, layers or collision switches). The gap between the two keeps a
 * resting contact from flickering. Ends caused between two ticks are reported with the next tick,
 * so every begin has its end.
 */
public final class StepData {
    private Body[] bodies = new Body[0];
    private int bodyCount;
    private float[] startX = new float[16];
    private float[] startY = new float[16];
    private float[] startAngle = new float[16];
    private Contact[] begun = new Contact[16];
    private int beginCount;
    private final BodyPairs ends = new BodyPairs();
    private Contact[] hit = new Contact[16];
    private float[] hitX = new float[16];
    private float[] hitY = new float[16];
    private float[] hitSpeed = new float[16];
    private int hitCount;
    private final BodyPairs sensorBegins = new BodyPairs();
    private final BodyPairs sensorEnds = new BodyPairs();
    private Constraint[] broken = new Constraint[4];
    private int brokenCount;
    private long tick;

    StepData() {
    }

    /** Starts a tick: forgets the last one's events, keeping the ends caused since it. */
    void begin(long tickNumber) {
        Arrays.fill(begun, 0, beginCount, null);
        Arrays.fill(hit, 0, hitCount, null);
        Arrays.fill(broken, 0, brokenCount, null);
        beginCount = 0;
        hitCount = 0;
        brokenCount = 0;
        ends.beginTick(true);
        sensorBegins.beginTick(false);
        sensorEnds.beginTick(true);
        tick = tickNumber;
    }

    /** Notes the simulated bodies and their poses before the solve moves them. */
    void recordStart(Body[] simulated, int count) {
        bodies = simulated;
        bodyCount = count;
        if (startX.length < count) {
            int size = Math.max(count, 2 * startX.length);
            startX = new float[size];
            startY = new float[size];
            startAngle = new float[size];
        }
        for (int i = 0; i < count; i++) {
            Body b = simulated[i];
            b.stepIndex = i;
            startX[i] = b.x;
            startY[i] = b.y;
            startAngle[i] = b.angle;
        }
    }

    /** Ends the tick: ends caused from now on belong to the next one. */
    void end() {
        ends.endTick();
        sensorBegins.endTick();
        sensorEnds.endTick();
    }

    void contactBegan(Contact c) {
        if (beginCount == begun.length) {
            begun = Arrays.copyOf(begun, 2 * beginCount);
        }
        begun[beginCount++] = c;
    }

    void contactHit(Contact c, int point, float speed) {
        if (hitCount == hit.length) {
            int size = 2 * hitCount;
            hit = Arrays.copyOf(hit, size);
            hitX = Arrays.copyOf(hitX, size);
            hitY = Arrays.copyOf(hitY, size);
            hitSpeed = Arrays.copyOf(hitSpeed, size);
        }
        hit[hitCount] = c;
        hitX[hitCount] = c.pointX(point);
        hitY[hitCount] = c.pointY(point);
        hitSpeed[hitCount++] = speed;
    }

    void sensorBegan(Body sensor, Body visitor) {
        sensorBegins.add(sensor, visitor);
    }

    void sensorEnded(Body sensor, Body visitor) {
        sensorEnds.add(sensor, visitor);
    }

    void constraintBroke(Constraint c) {
        if (brokenCount == broken.length) {
            broken = Arrays.copyOf(broken, 2 * brokenCount);
        }
        broken[brokenCount++] = c;
    }

    void contactEnded(Contact c) {
        ends.add(c.bodyA, c.bodyB);
    }

    /**
     * The tick this describes.
     *
     * @return the tick's number (the world's tick count before it ran)
     */
    public long getTick() {
        return tick;
    }

    /**
     * The number of bodies the tick simulated (see {@link Body#isSimulated()}).
     *
     * @return the count
     */
    public int getBodyCount() {
        return bodyCount;
    }

    /**
     * A simulated body, in world order.
     *
     * @param index 0 to {@link #getBodyCount()} − 1
     * @return the body
     */
    public Body getBody(int index) {
        checkBody(index);
        return bodies[index];
    }

    /**
     * Where a body is in this list, in O(1).
     *
     * @param body a body
     * @return its index, or −1 when the tick did not simulate it
     */
    public int indexOf(Body body) {
        int i = body.stepIndex;
        return i >= 0 && i < bodyCount && bodies[i] == body ? i : -1;
    }

    /**
     * @param index 0 to {@link #getBodyCount()} − 1
     * @return the body's x at the tick's start (px)
     */
    public float getStartX(int index) {
        checkBody(index);
        return startX[index];
    }

    /**
     * @param index 0 to {@link #getBodyCount()} − 1
     * @return the body's y at the tick's start (px)
     */
    public float getStartY(int index) {
        checkBody(index);
        return startY[index];
    }

    /**
     * @param index 0 to {@link #getBodyCount()} − 1
     * @return the body's angle at the tick's start (rad)
     */
    public float getStartAngle(int index) {
        checkBody(index);
        return startAngle[index];
    }

    /**
     * The number of contacts that began touching in the tick.
     *
     * @return the count
     */
    public int getBeginCount() {
        return beginCount;
    }

    /**
     * A contact that began touching, in the order found: those the narrowphase found, in the order it
     * keeps its contacts, then, substep by substep, those a bounce made touch, each substep's in that
     * order too; the same for any thread count. Valid until the next tick.
     *
     * @param index 0 to {@link #getBeginCount()} − 1
     * @return the contact
     */
    public Contact getBeginContact(int index) {
        if (index < 0 || index >= beginCount) {
            throw new IndexOutOfBoundsException("StepData.getBeginContact: index " + index + " of " + beginCount);
        }
        return begun[index];
    }

    /**
     * The number of contacts that stopped touching in the tick, including those ended by the
     * application's changes before it (their contact objects are gone).
     *
     * @return the count
     */
    public int getEndCount() {
        return ends.count();
    }

    /**
     * The first body of a contact that stopped touching.
     *
     * @param index 0 to {@link #getEndCount()} − 1
     * @return the body
     */
    public Body getEndBodyA(int index) {
        return ends.get(index, 0, "getEndBodyA");
    }

    /**
     * The second body of a contact that stopped touching.
     *
     * @param index 0 to {@link #getEndCount()} − 1
     * @return the body, or null for a landscape segment
     */
    public Body getEndBodyB(int index) {
        return ends.get(index, 1, "getEndBodyB");
    }

    /**
     * The number of hits in the tick: contacts that took an impulse at a point approaching faster
     * than {@link Simulation#getHitEventThreshold()} (none while that is infinite, the default).
     *
     * @return the count
     */
    public int getHitCount() {
        return hitCount;
    }

    /**
     * A contact that was hit, in the order the narrowphase keeps its contacts (as the contacts that
     * began touching), the same for any thread count. Valid until the next tick.
     *
     * @param index 0 to {@link #getHitCount()} − 1
     * @return the contact
     */
    public Contact getHitContact(int index) {
        checkHit(index);
        return hit[index];
    }

    /**
     * @param index 0 to {@link #getHitCount()} − 1
     * @return x of the hit's fastest point (px)
     */
    public float getHitX(int index) {
        checkHit(index);
        return hitX[index];
    }

    /**
     * @param index 0 to {@link #getHitCount()} − 1
     * @return y of the hit's fastest point (px)
     */
    public float getHitY(int index) {
        checkHit(index);
        return hitY[index];
    }

    /**
     * @param index 0 to {@link #getHitCount()} − 1
     * @return the speed at which that point approached, along the normal (px/s)
     */
    public float getHitSpeed(int index) {
        checkHit(index);
        return hitSpeed[index];
    }

    /**
     * The number of bodies that began overlapping a sensor ({@link Body#setSensor}) in the tick.
     *
     * @return the count
     */
    public int getSensorBeginCount() {
        return sensorBegins.count();
    }

    /**
     * @param index 0 to {@link #getSensorBeginCount()} − 1
     * @return the sensor
     */
    public Body getSensorBeginSensor(int index) {
        return sensorBegins.get(index, 0, "getSensorBeginSensor");
    }

    /**
     * @param index 0 to {@link #getSensorBeginCount()} − 1
     * @return the body that began overlapping it
     */
    public Body getSensorBeginVisitor(int index) {
        return sensorBegins.get(index, 1, "getSensorBeginVisitor");
    }

    /**
     * The number of bodies that stopped overlapping a sensor in the tick, including those removed
     * from the world and sensors removed or made solid (whose visitors all end).
     *
     * @return the count
     */
    public int getSensorEndCount() {
        return sensorEnds.count();
    }

    /**
     * @param index 0 to {@link #getSensorEndCount()} − 1
     * @return the sensor
     */
    public Body getSensorEndSensor(int index) {
        return sensorEnds.get(index, 0, "getSensorEndSensor");
    }

    /**
     * @param index 0 to {@link #getSensorEndCount()} − 1
     * @return the body that stopped overlapping it
     */
    public Body getSensorEndVisitor(int index) {
        return sensorEnds.get(index, 1, "getSensorEndVisitor");
    }

    private void checkHit(int index) {
        if (index < 0 || index >= hitCount) {
            throw new IndexOutOfBoundsException("StepData.getHit: index " + index + " of " + hitCount);
        }
    }

    private void checkBody(int index) {
        if (index < 0 || index >= bodyCount) {
            throw new IndexOutOfBoundsException("StepData.getBody: index " + index + " of " + bodyCount);
        }
    }

    /**
     * The number of constraints that broke in the tick: their force exceeded their
     * {@link Constraint#getBreakForce()}, and the world removed them as the tick ended.
     *
     * @return the count
     */
    public int getBrokenCount() {
        return brokenCount;
    }

    /**
     * A constraint that broke in the tick (no longer in the world).
     *
     * @param index 0 to {@link #getBrokenCount()} − 1
     * @return the constraint; its {@link Constraint#getForce()} is the force that broke it
     */
    public Constraint getBrokenConstraint(int index) {
        if (index < 0 || index >= brokenCount) {
            throw new IndexOutOfBoundsException("StepData.getBrokenConstraint: index " + index + " of " + brokenCount);
        }
        return broken[index];
    }
}
