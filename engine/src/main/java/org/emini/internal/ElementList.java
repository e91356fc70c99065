package org.emini.internal;

import java.util.Arrays;

/**
 * One of a world's ordered lists of elements (constraints, external forces, events): each element
 * at most once, in the order added, with adds and removes queued while a tick runs. Its messages
 * name the world's call, e.g. {@code World.addEvent}.
 *
 * @param <T> the element type
 */
public final class ElementList<T> implements ChangeQueue.Target {
    private final ChangeQueue changes;
    private final String kind;
    private final String param;
    private T[] items;
    private int count;

    /**
     * @param changes the world's queue of changes made during a tick
     * @param initial an empty array of the element type, its length the first capacity (≥ 1)
     * @param kind the element's name in the world's calls, e.g. {@code "Event"} for {@code World.addEvent}
     * @param param the argument's name in messages, e.g. {@code "event"}
     */
    public ElementList(ChangeQueue changes, T[] initial, String kind, String param) {
        this.changes = changes;
        this.items = initial;
        this.kind = kind;
        this.param = param;
    }

    /**
     * Adds an element at the end (when the tick ends, during one).
     *
     * @param item the element, not null, not already there
     */
    public void add(T item) {
        String where = "World.add" + kind;
        Check.notNull(where, param, item);
        boolean there = indexOf(item) >= 0;
        if (changes.isOpen() ? changes.willContain(this, item, there) : there) {
            throw new IllegalArgumentException(where + ": the " + param + " is already in this world");
        }
        if (changes.isOpen()) {
            changes.add(this, item, true);
            return;
        }
        if (count == items.length) {
            items = Arrays.copyOf(items, 2 * count);
        }
        items[count++] = item;
    }

    /**
     * Removes an element, keeping the others' order (when the tick ends, during one).
     *
     * @param item the element
     * @return true when it was there (during a tick: will be, when the tick ends)
     */
    public boolean remove(Object item) {
        int i = indexOf(item);
        if (changes.isOpen()) {
            boolean there = item != null && changes.willContain(this, item, i >= 0);
            if (there) {
                changes.add(this, item, false);
            }
            return there;
        }
        if (i < 0) {
            return false;
        }
        System.arraycopy(items, i + 1, items, i, count - i - 1);
        items[--count] = null;
        return true;
    }

    @Override
    @SuppressWarnings("unchecked")
    public void apply(Object item, boolean add) {
        if (add) {
            add((T) item);
        } else {
            remove(item);
        }
    }

    /** @return the number of elements */
    public int count() {
        return count;
    }

    /**
     * @param index 0 to {@link #count()} − 1
     * @return the element
     */
    public T get(int index) {
        if (index < 0 || index >= count) {
            throw new IndexOutOfBoundsException("World.get" + kind + ": index " + index + " of " + count);
        }
        return items[index];
    }

    /** @return the elements in order, in the first {@link #count()} places; read only */
    public T[] array() {
        return items;
    }

    /**
     * Keeps only the first {@code kept} elements of {@link #array()}, after the caller moved those
     * to keep to the front (for removing many at once in one pass).
     *
     * @param kept the new count
     */
    public void truncate(int kept) {
        Arrays.fill(items, kept, count, null);
        count = kept;
    }

    private int indexOf(Object item) {
        for (int i = 0; i < count; i++) {
            if (items[i] == item) {
                return i;
            }
        }
        return -1;
    }
}
