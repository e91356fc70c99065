package org.emini.event;

/**
 * A set of objects compared by identity, for the trigger-once memory of an event. Open addressing
 * over one array; it allocates only when it grows, so a tick's checks allocate nothing.
 */
final class IdentitySet {
    private Object[] table = new Object[8];
    private int size;

    boolean contains(Object o) {
        Object[] t = table;
        int mask = t.length - 1;
        for (int i = slot(o, mask); t[i] != null; i = (i + 1) & mask) {
            if (t[i] == o) {
                return true;
            }
        }
        return false;
    }

    void add(Object o) {
        if (contains(o)) {
            return;
        }
        // Keep the table at most half full so probe runs stay short.
        if (2 * (size + 1) > table.length) {
            Object[] old = table;
            table = new Object[old.length * 2];
            for (Object e : old) {
                if (e != null) {
                    insert(e);
                }
            }
        }
        insert(o);
        size++;
    }

    void clear() {
        java.util.Arrays.fill(table, null);
        size = 0;
    }

    private void insert(Object o) {
        Object[] t = table;
        int mask = t.length - 1;
        int i = slot(o, mask);
        while (t[i] != null) {
            i = (i + 1) & mask;
        }
        t[i] = o;
    }

    private static int slot(Object o, int mask) {
        return (System.identityHashCode(o) * 0x9E3779B9 >>> 7) & mask;
    }
}
