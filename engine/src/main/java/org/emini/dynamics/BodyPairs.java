package org.emini.dynamics;

import java.util.Arrays;

/**
 * A list of pairs of bodies for the step data (contacts or sensor overlaps that ended or began),
 * which may keep the pairs added after a tick ended for the next one: what the application ends
 * between two ticks is reported with the next.
 */
final class BodyPairs {
    private Body[] pairs = new Body[16];
    private int count;
    // Pairs added by the last tick; those after it came between ticks.
    private int ofTick;
    private boolean ticking;

    void add(Body first, Body second) {
        if (2 * count == pairs.length) {
            pairs = Arrays.copyOf(pairs, 2 * pairs.length);
        }
        pairs[2 * count] = first;
        pairs[2 * count++ + 1] = second;
    }

    /** Starts a tick: forgets the last tick's pairs, keeping those added since when asked to. */
    void beginTick(boolean keepSince) {
        int since = keepSince ? count - ofTick : 0;
        System.arraycopy(pairs, 2 * ofTick, pairs, 0, 2 * since);
        Arrays.fill(pairs, 2 * since, 2 * count, null);
        count = since;
        ofTick = 0;
        ticking = true;
    }

    void endTick() {
        ofTick = count;
        ticking = false;
    }

    /** @return the tick's pairs (while it runs: so far) */
    int count() {
        return ticking ? count : ofTick;
    }

    Body get(int index, int which, String where) {
        int n = count();
        if (index < 0 || index >= n) {
            throw new IndexOutOfBoundsException("StepData." + where + ": index " + index + " of " + n);
        }
        return pairs[2 * index + which];
    }
}
