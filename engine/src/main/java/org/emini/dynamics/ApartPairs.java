package org.emini.dynamics;

import java.util.Arrays;

/**
 * A flat copy, by contact index, of what the narrowphase reads to find a pair it found apart still
 * apart ({@link ManifoldReuse#staysApart}): the parts' keys, the gap and the pose it was measured
 * at, and the friction and elasticity products it last set. In a crowd a third or more of the pairs
 * whose fat boxes overlap are apart (8,200 of 19,000 a tick in 5,000 falling bodies), and the first
 * read of each one's contact object, scattered in memory, was a large part of the narrowphase's time.
 *
 * <p>A copy is valid from the narrowphase's last look at the contact until the contact changes: the
 * narrowphase writes or clears it each time it reads the object (a contact with points or waiting
 * for its filter is cleared), a filter change clears it, a new contact starts without one, and the
 * contact moved into a destroyed one's index takes its copy along. The narrowphase's threads write distinct indices, and nothing grows while they run.
 */
final class ApartPairs {
    private static final int GAP = 0;
    private static final int POSE_X = 1;
    private static final int POSE_Y = 2;
    private static final int POSE_C = 3;
    private static final int POSE_S = 4;
    private static final int FRICTION = 5;
    private static final int RESTITUTION = 6;
    private static final int FS = 8;

    private float[] f = new float[16 * FS];
    private int[] keys = new int[16 * 2];
    private boolean[] valid = new boolean[16];

    /** Room for indices below capacity; a new index starts without a copy. */
    void ensure(int capacity) {
        if (valid.length < capacity) {
            int size = Math.max(capacity, 2 * valid.length);
            f = Arrays.copyOf(f, size * FS);
            keys = Arrays.copyOf(keys, size * 2);
            valid = Arrays.copyOf(valid, size);
        }
    }

    /**
     * Copies a contact the narrowphase has just read and left between two bodies with no points and a
     * gap remembered, or clears its copy otherwise.
     */
    void note(Contact c) {
        int i = c.index;
        if (c.pointCount != 0 || c.apartGap == 0f || c.segmentSlot >= 0 || c.filterDirty) {
            valid[i] = false;
            return;
        }
        int o = i * FS;
        f[o + GAP] = c.apartGap;
        f[o + POSE_X] = c.poseX;
        f[o + POSE_Y] = c.poseY;
        f[o + POSE_C] = c.poseC;
        f[o + POSE_S] = c.poseS;
        f[o + FRICTION] = c.friction;
        f[o + RESTITUTION] = c.restitution;
        keys[2 * i] = c.keyA;
        keys[2 * i + 1] = c.keyB;
        valid[i] = true;
    }

    void clear(int index) {
        valid[index] = false;
    }

    /** The contact at index from moved to index to (a swap-remove). */
    void move(int from, int to) {
        System.arraycopy(f, from * FS, f, to * FS, FS);
        keys[2 * to] = keys[2 * from];
        keys[2 * to + 1] = keys[2 * from + 1];
        valid[to] = valid[from];
        valid[from] = false;
    }

    boolean isValid(int index) {
        return valid[index];
    }

    int keyA(int index) {
        return keys[2 * index];
    }

    int keyB(int index) {
        return keys[2 * index + 1];
    }

    /** {@link ManifoldReuse#staysApart} from the copy's gap and pose. */
    boolean staysApart(int index, Body a, Body b, float radiusA, float radiusB, float margin) {
        int o = index * FS;
        return ManifoldReuse.staysApart(f[o + GAP], f[o + POSE_X], f[o + POSE_Y], f[o + POSE_C], f[o + POSE_S], a, b, radiusA,
            radiusB, margin);
    }

    /** Whether the contact's friction and elasticity are these products still (so nothing is to be set). */
    boolean sameFactors(int index, float friction, float restitution) {
        int o = index * FS;
        return f[o + FRICTION] == friction && f[o + RESTITUTION] == restitution;
    }
}
