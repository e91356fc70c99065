package org.emini.internal;

import java.util.Arrays;

/**
 * The structural changes asked for while a tick runs (from an external force, a constraint or an
 * event listener), applied in the order they were asked for when the tick ends. Until then the
 * world's lists stay as they were when the tick began, so nothing that walks them mid-tick (the
 * solver, the events) sees an element vanish under it. One queue serves every list of a world, so
 * changes to different lists keep their order too.
 */
public final class ChangeQueue {
    /** Where a queued change lands: one of the world's lists, or a setter. */
    public interface Target {
        /**
         * Makes the change now.
         *
         * @param item the element
         * @param add true to add it, false to remove it (setters ignore it)
         */
        void apply(Object item, boolean add);
    }

    private boolean open;
    private Target[] targets = new Target[8];
    private Object[] items = new Object[8];
    private boolean[] adds = new boolean[8];
    private int count;

    /** @return true while a tick runs: changes are queued */
    public boolean isOpen() {
        return open;
    }

    /**
     * Starts queueing, at the start of a tick.
     *
     * @param reentered the message when a tick is already running (ticks are not re-entrant)
     */
    public void open(String reentered) {
        if (open) {
            throw new IllegalStateException(reentered);
        }
        open = true;
    }

    /**
     * Queues a change.
     *
     * @param target where it lands
     * @param item the element
     * @param add add or remove
     */
    public void add(Target target, Object item, boolean add) {
        if (count == targets.length) {
            targets = Arrays.copyOf(targets, 2 * count);
            items = Arrays.copyOf(items, 2 * count);
            adds = Arrays.copyOf(adds, 2 * count);
        }
        targets[count] = target;
        items[count] = item;
        adds[count++] = add;
    }

    /**
     * Whether the item ends up in the target's list, given that it is in it now or not: the last
     * queued add or remove of it decides.
     *
     * @param target the list
     * @param item the element
     * @param containedNow whether the list holds it now
     * @return whether it will hold it when the tick ends
     */
    public boolean willContain(Target target, Object item, boolean containedNow) {
        boolean contained = containedNow;
        for (int i = 0; i < count; i++) {
            if (items[i] == item && targets[i] == target) {
                contained = adds[i];
            }
        }
        return contained;
    }

    /** Stops queueing and applies the changes in order, forgetting them also when one fails. */
    public void close() {
        open = false;
        int n = count;
        try {
            for (int i = 0; i < n; i++) {
                targets[i].apply(items[i], adds[i]);
            }
        } finally {
            count = 0;
            Arrays.fill(targets, 0, n, null);
            Arrays.fill(items, 0, n, null);
        }
    }
}
