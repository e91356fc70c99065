package org.emini.dynamics;

import java.util.Arrays;

/**
 * What the last tick did, read-only until the next one: the bodies it simulated, each with its pose
 * at the tick's start (its end pose is the body's own), and the contacts that began and stopped
 * touching. Particles, events and the application read it instead of recomputing it.
 *
 * <p>A contact touches when the narrowphase, at the tick's start, finds a point of it at or inside
 * zero separation; it stops touching when none is within {@link SolverSettings#getSpeculativeDistance()}
 * any more, or when its bodies' boxes part (the contact ends). The gap between the two keeps a
 * resting contact from flickering. A contact ends without a report when the application removes
 * one of its bodies or changes its shape, layers or collision switches between ticks.
 */
public final class StepData {
    private Body[] bodies = new Body[0];
    private int bodyCount;
    private float[] startX = new float[16];
    private float[] startY = new float[16];
    private float[] startAngle = new float[16];
    private Contact[] begun = new Contact[16];
    private int beginCount;
    private Body[] endA = new Body[16];
    private Body[] endB = new Body[16];
    private int endCount;
    private long tick;
    private boolean recording;

    StepData() {
    }

    /** Starts a tick: forgets the last one's contacts. */
    void begin(long tickNumber) {
        Arrays.fill(begun, 0, beginCount, null);
        Arrays.fill(endA, 0, endCount, null);
        Arrays.fill(endB, 0, endCount, null);
        beginCount = 0;
        endCount = 0;
        tick = tickNumber;
        recording = true;
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

    /** Stops recording contact changes: the application's own changes between ticks are not reported. */
    void end() {
        recording = false;
    }

    void contactBegan(Contact c) {
        if (beginCount == begun.length) {
            begun = Arrays.copyOf(begun, 2 * beginCount);
        }
        begun[beginCount++] = c;
    }

    void contactEnded(Contact c) {
        if (!recording) {
            return;
        }
        if (endCount == endA.length) {
            endA = Arrays.copyOf(endA, 2 * endCount);
            endB = Arrays.copyOf(endB, 2 * endCount);
        }
        endA[endCount] = c.bodyA;
        endB[endCount++] = c.bodyB;
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
     * A contact that began touching, in the order found. Valid until the next tick.
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
     * The number of contacts that stopped touching in the tick (their contact may be gone).
     *
     * @return the count
     */
    public int getEndCount() {
        return endCount;
    }

    /**
     * The first body of a contact that stopped touching.
     *
     * @param index 0 to {@link #getEndCount()} − 1
     * @return the body
     */
    public Body getEndBodyA(int index) {
        checkEnd(index);
        return endA[index];
    }

    /**
     * The second body of a contact that stopped touching.
     *
     * @param index 0 to {@link #getEndCount()} − 1
     * @return the body, or null for a landscape segment
     */
    public Body getEndBodyB(int index) {
        checkEnd(index);
        return endB[index];
    }

    private void checkBody(int index) {
        if (index < 0 || index >= bodyCount) {
            throw new IndexOutOfBoundsException("StepData.getBody: index " + index + " of " + bodyCount);
        }
    }

    private void checkEnd(int index) {
        if (index < 0 || index >= endCount) {
            throw new IndexOutOfBoundsException("StepData.getEnd: index " + index + " of " + endCount);
        }
    }
}
