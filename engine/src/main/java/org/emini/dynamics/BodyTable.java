package org.emini.dynamics;

/**
 * The world's bodies two ways: in insertion order (the index of {@link Simulation#getBody}, which events
 * and the original's ids use), and by id (ids grow with insertion and removal keeps the order, so a
 * binary search finds them). The broadphase names bodies by their parts' keys ({@link PartKeys}).
 *
 * <p>Removal leaves a hole that the next ordered read closes in one pass: removing k bodies costs
 * O(k) plus one O(n) compaction, not O(k·n).
 */
final class BodyTable {
    private Body[] ordered = new Body[16];
    // Entries in ordered, holes included, and holes not yet closed.
    private int end;
    private int holes;
    private int nextId;

    /** Gives the body its id and index and appends it. */
    void add(Body body) {
        closeHoles();
        if (end == ordered.length) {
            ordered = java.util.Arrays.copyOf(ordered, 2 * end);
        }
        body.id = nextId++;
        body.worldIndex = end;
        ordered[end++] = body;
    }

    /** Takes the body out, leaving a hole in the order. */
    void remove(Body body) {
        ordered[body.worldIndex] = null;
        holes++;
        body.worldIndex = -1;
    }

    int count() {
        return end - holes;
    }

    /** The bodies in order, holes closed: read {@link #count()} of them. */
    Body[] ordered() {
        closeHoles();
        return ordered;
    }

    Body findById(int id) {
        Body[] list = ordered();
        int lo = 0;
        int hi = end - 1;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            int midId = list[mid].id;
            if (midId < id) {
                lo = mid + 1;
            } else if (midId > id) {
                hi = mid - 1;
            } else {
                return list[mid];
            }
        }
        return null;
    }

    /** Closes the holes removals left, so every body's index is its place in the order. */
    void closeHoles() {
        if (holes == 0) {
            return;
        }
        int kept = 0;
        for (int i = 0; i < end; i++) {
            Body b = ordered[i];
            if (b != null) {
                b.worldIndex = kept;
                ordered[kept++] = b;
            }
        }
        java.util.Arrays.fill(ordered, kept, end, null);
        end = kept;
        holes = 0;
    }
}
